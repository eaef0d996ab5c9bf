import { describe, expect, it } from 'vitest';
import { Matrix4, OrthographicCamera, PerspectiveCamera, Vector3 } from 'three';
import {
  cross,
  dragPlane,
  gridSpacing,
  intersectPlane,
  pickNearest,
  pickPolyline,
  projectToScreen,
  snapToGrid,
  snapToObjects,
  workingPlane,
  type Vec3,
} from './math';

function viewProj(cam: OrthographicCamera | PerspectiveCamera): Matrix4 {
  cam.updateMatrixWorld();
  return new Matrix4().multiplyMatrices(cam.projectionMatrix, cam.matrixWorldInverse);
}

describe('working planes', () => {
  // Thesis app. 8.1/8.2: top draws in X-Y, front in Z-X, side in Y-Z; each normal is u × v.
  it('follow the view as in appendix 8', () => {
    expect(workingPlane('top').normal).toEqual([0, 0, 1]);
    expect(workingPlane('front').u).toEqual([1, 0, 0]);
    expect(workingPlane('front').v).toEqual([0, 0, 1]);
    expect(workingPlane('side').u).toEqual([0, 1, 0]);
    for (const v of ['top', 'front', 'side', 'persp'] as const) {
      const p = workingPlane(v);
      expect(cross(p.u, p.v)).toEqual(p.normal.map((x) => x + 0));
    }
  });

  // A ray down the -Z axis meets the top plane at its (x, y), hand-computed.
  it('intersect rays at the closed-form point', () => {
    const hit = intersectPlane({ origin: [3, 4, 10], direction: [0, 0, -2] }, workingPlane('top'));
    expect(hit).toEqual([3, 4, 0]);
    const slanted = intersectPlane(
      { origin: [0, -5, 1], direction: [1, 1, 1] },
      workingPlane('front'),
    );
    expect(slanted).toEqual([5, 0, 6]);
    expect(
      intersectPlane({ origin: [0, 0, 1], direction: [1, 0, 0] }, workingPlane('top')),
    ).toBeNull();
    expect(
      intersectPlane({ origin: [0, 0, 1], direction: [0, 0, 1] }, workingPlane('top')),
    ).toBeNull();
  });

  // A dragged point keeps its depth: the drag plane of the front view through (1, 7, 2) is y = 7.
  it('drag plane keeps the point depth', () => {
    const p = dragPlane('front', [1, 7, 2]);
    const hit = intersectPlane({ origin: [4, -20, 9], direction: [0, 1, 0] }, p);
    expect(hit).toEqual([4, 7, 9]);
  });
});

describe('snapping', () => {
  // Rounding of in-plane coordinates to the grid, by hand: 12.4 → 10, 17.6 → 20 at spacing 10.
  it('rounds in-plane coordinates and keeps depth', () => {
    expect(snapToGrid([12.4, 17.6, 0], workingPlane('top'), 10)).toEqual([10, 20, 0]);
    expect(snapToGrid([0.26, 3, -0.74], workingPlane('front'), 0.5)).toEqual([0.5, 3, -0.5]);
    expect(() => snapToGrid([0, 0, 0], workingPlane('top'), 0)).toThrow(/spacing 0/);
  });

  // Grid spacing is the smallest 1-2-5 step covering the minimum pixels.
  it('chooses 1-2-5 grid steps', () => {
    expect(gridSpacing(0.1, 16)).toBe(2);
    expect(gridSpacing(1, 10)).toBe(10);
    expect(gridSpacing(0.03, 10)).toBeCloseTo(0.5, 12);
  });
});

describe('picking', () => {
  // Projection agrees with three.js's own Vector3.project on a perspective camera.
  it('projects like three.js', () => {
    const cam = new PerspectiveCamera(45, 2, 0.1, 1000);
    cam.position.set(30, -40, 50);
    cam.up.set(0, 0, 1);
    cam.lookAt(0, 0, 0);
    const vp = viewProj(cam);
    const p: Vec3 = [3, 5, -2];
    const s = projectToScreen(p, vp.elements, 800, 400)!;
    const ref = new Vector3(...p).project(cam);
    expect(s[0]).toBeCloseTo(((ref.x + 1) / 2) * 800, 9);
    expect(s[1]).toBeCloseTo(((1 - ref.y) / 2) * 400, 9);
  });

  // In a top orthographic view of 200×200 px over [-10, 10]², (5, 0) sits at pixel (150, 100).
  it('picks the nearest point within the radius', () => {
    const cam = new OrthographicCamera(-10, 10, 10, -10, 0.1, 100);
    cam.position.set(0, 0, 50);
    cam.lookAt(0, 0, 0);
    const vp = viewProj(cam).elements;
    const pts: Vec3[] = [
      [0, 0, 0],
      [5, 0, 0],
      [5.2, 0, 0],
    ];
    expect(pickNearest([151, 100], pts, vp, 200, 200, 4)).toEqual({ index: 1, distance: 1 });
    expect(pickNearest([180, 100], pts, vp, 200, 200, 4)).toBeNull();
    // On the segment between samples 0 and 1, nearer to 1.
    const hit = pickPolyline([140, 101], pts, vp, 200, 200, 3);
    expect(hit?.index).toBe(1);
    expect(hit?.distance).toBeCloseTo(1, 9);
  });
});

describe('object snap', () => {
  // The top view of a 100 × 100 window onto [-50, 50]²: x right, y up, one unit per pixel.
  const m = [1 / 50, 0, 0, 0, 0, 1 / 50, 0, 0, 0, 0, -1 / 50, 0, 0, 0, 0, 1];
  const px = (x: number, y: number): [number, number] => [x + 50, 50 - y];
  const targets = {
    points: [
      [10, 10, 0],
      [12, 10, 0],
    ] as Vec3[],
    polylines: [
      [
        [-40, -20, 0],
        [0, -20, 0],
        [40, 20, 0],
      ],
    ] as Vec3[][],
  };
  it('lands exactly on the nearest point within the radius, before any curve', () => {
    const s = snapToObjects(px(10.6, 11), targets, m, 100, 100, 6)!;
    expect(s.point).toEqual([10, 10, 0]);
    expect(s.kind).toBe('point');
    expect(s.index).toBe(0);
    expect(s.distance).toBeCloseTo(Math.hypot(0.6, 1), 12);
    expect(snapToObjects(px(11.6, 10), targets, m, 100, 100, 6)!.point).toEqual([12, 10, 0]);
  });
  it('lands on the nearest point of a curve when no point is near', () => {
    const s = snapToObjects(px(-10, -17), targets, m, 100, 100, 6)!;
    expect(s.kind).toBe('curve');
    expect(s.point[0]).toBeCloseTo(-10, 12);
    expect(s.point[1]).toBeCloseTo(-20, 12);
    // On the slanted segment y = x − 20: the foot of the perpendicular from (30, 0) is (25, 5).
    const t = snapToObjects(px(30, 0), targets, m, 100, 100, 8)!;
    expect(t.point[0]).toBeCloseTo(25, 12);
    expect(t.point[1]).toBeCloseTo(5, 12);
    expect(t.distance).toBeCloseTo(Math.hypot(5, 5), 12);
  });
  it('gives nothing beyond the radius', () => {
    expect(snapToObjects(px(-10, 0), targets, m, 100, 100, 6)).toBeNull();
  });
});
