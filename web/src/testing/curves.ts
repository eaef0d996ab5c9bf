// Curves shared by the unit tests and the e2e specs (which import it from
// ../src/testing): one definition, so a test that reads a value off one of
// them reads the same curve everywhere.

import type { CurveFile } from '../api/types';

type Nurbs = Extract<CurveFile, { kind: 'nurbs' }>;

/** A planar cubic arch in the X-Y plane, clamped, two interior knots (0.3, 0.6), six control points. */
export const arch: Nurbs = {
  kind: 'nurbs',
  degree: 3,
  knots: [0, 0, 0, 0, 0.3, 0.6, 1, 1, 1, 1],
  control_points: [
    [0, 0, 0],
    [15, 25, 0],
    [40, 35, 0],
    [65, 30, 0],
    [85, 10, 0],
    [100, 0, 0],
  ],
};
