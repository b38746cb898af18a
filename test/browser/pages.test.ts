/** Shard 1 of 3 of the gallery page checks (./page-contract), with the gallery and the phone toolbar. */
import { describePages } from './page-contract';

describePages(0, 3);
