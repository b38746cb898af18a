/** Shard 3 of 3 of the gallery page checks (./page-contract). */
import { describePages } from './page-contract';

describePages(2, 3);
