import { BALL_ROWS_3D } from './ball-joint-3d.js';
import { DISTANCE_ROWS_3D } from './distance-joint-3d.js';
import { FIXED_ROWS_3D } from './fixed-joint-3d.js';
import { HINGE_ROWS_3D } from './hinge-joint-3d.js';
import { SLIDER_ROWS_3D } from './slider-joint-3d.js';
import { useJointType3D } from './solver-3d.js';
import { Joint3DType } from './store-3d.js';

/**
 * Hands the 3D joint solver every type's rows (useJointType3D): restore calls it, since a snapshot may
 * hold joints of any type that the program never made with an add call.
 * @category Joints and ropes
 */
export function useEveryJointType3D(): void {
  useJointType3D(Joint3DType.Distance, DISTANCE_ROWS_3D);
  useJointType3D(Joint3DType.Ball, BALL_ROWS_3D);
  useJointType3D(Joint3DType.Hinge, HINGE_ROWS_3D);
  useJointType3D(Joint3DType.Fixed, FIXED_ROWS_3D);
  useJointType3D(Joint3DType.Slider, SLIDER_ROWS_3D);
}
