// Browser-side viewport math: working planes, rays, picking and snapping.
// Pure functions on plain arrays so they are unit-tested without a GPU; the
// page owns picking, snapping and drawing, the server owns all curve geometry.

export type Vec3 = readonly [number, number, number];

/** The four viewports of appendix 8.7. */
export type ViewName = 'top' | 'front' | 'side' | 'persp';

export const VIEW_NAMES: readonly ViewName[] = ['top', 'front', 'side', 'persp'];

/**
 * A working plane: origin + two in-plane unit axes (u, v) and the normal u × v.
 * Points clicked in a view land on the plane of that view.
 */
export interface WorkingPlane {
  readonly origin: Vec3;
  readonly u: Vec3;
  readonly v: Vec3;
  readonly normal: Vec3;
}

export const add = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const scale = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];
export const dot = (a: Vec3, b: Vec3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
export const norm = (a: Vec3): number => Math.hypot(a[0], a[1], a[2]);

/**
 * The working plane of a view (thesis appendix 8.1/8.2): top draws in X-Y
 * (z = 0), front in Z-X (y = 0), side in Y-Z (x = 0). The perspective view
 * draws in X-Y like the top view. `depth` offsets the plane along its normal.
 */
export function workingPlane(view: ViewName, depth = 0): WorkingPlane {
  switch (view) {
    case 'top':
    case 'persp':
      return { origin: [0, 0, depth], u: [1, 0, 0], v: [0, 1, 0], normal: [0, 0, 1] };
    case 'front':
      // Seen from -Y: X to the right, Z up; the normal points at the viewer.
      return { origin: [0, depth, 0], u: [1, 0, 0], v: [0, 0, 1], normal: [0, -1, 0] };
    case 'side':
      // Seen from +X: Y to the right, Z up.
      return { origin: [depth, 0, 0], u: [0, 1, 0], v: [0, 0, 1], normal: [1, 0, 0] };
  }
}

/** A ray origin + t·direction (direction need not be unit length). */
export interface Ray {
  readonly origin: Vec3;
  readonly direction: Vec3;
}

/**
 * Where a ray meets a plane, or null when it runs parallel to it (|d·n| below
 * 1e-12 relative to |d|) or the plane is behind the ray's origin.
 */
export function intersectPlane(ray: Ray, plane: WorkingPlane): Vec3 | null {
  const denom = dot(ray.direction, plane.normal);
  if (Math.abs(denom) <= 1e-12 * norm(ray.direction)) return null;
  const t = dot(sub(plane.origin, ray.origin), plane.normal) / denom;
  if (t < 0) return null;
  return add(ray.origin, scale(ray.direction, t));
}

/** In-plane coordinates (u, v) of a point of the plane. */
export function toPlane(p: Vec3, plane: WorkingPlane): [number, number] {
  const d = sub(p, plane.origin);
  return [dot(d, plane.u), dot(d, plane.v)];
}

/** The 3-D point at in-plane coordinates (u, v). */
export function fromPlane(u: number, v: number, plane: WorkingPlane): Vec3 {
  return add(plane.origin, add(scale(plane.u, u), scale(plane.v, v)));
}

/**
 * Snap a point of the working plane to the grid of that plane (spacing > 0):
 * its in-plane coordinates are rounded to multiples of the spacing, the depth
 * along the normal is kept.
 */
export function snapToGrid(p: Vec3, plane: WorkingPlane, spacing: number): Vec3 {
  if (!(spacing > 0) || !Number.isFinite(spacing)) {
    throw new RangeError(`grid spacing ${spacing} must be a positive finite number`);
  }
  const [u, v] = toPlane(p, plane);
  const depth = dot(sub(p, plane.origin), plane.normal);
  const snapped = fromPlane(
    Math.round(u / spacing) * spacing,
    Math.round(v / spacing) * spacing,
    plane,
  );
  return add(snapped, scale(plane.normal, depth));
}

/**
 * A grid spacing of 1, 2 or 5 × 10^k so that one grid cell covers at least
 * `minPixels` on screen, given the world units per pixel of the view.
 */
export function gridSpacing(worldPerPixel: number, minPixels = 16): number {
  if (!(worldPerPixel > 0) || !Number.isFinite(worldPerPixel)) {
    throw new RangeError(`world units per pixel ${worldPerPixel} must be positive and finite`);
  }
  const target = worldPerPixel * minPixels;
  const exp = Math.floor(Math.log10(target));
  const base = 10 ** exp;
  for (const m of [1, 2, 5, 10]) {
    if (m * base >= target * (1 - 1e-12)) return m * base;
  }
  return 10 * base;
}

/** A 4×4 matrix in column-major order (three.js `Matrix4.elements`). */
export type Mat4 = ArrayLike<number>;

/**
 * Project a world point to pixel coordinates of a viewport of width × height
 * through a column-major view-projection matrix. Returns null behind the camera.
 */
export function projectToScreen(
  p: Vec3,
  viewProj: Mat4,
  width: number,
  height: number,
): [number, number] | null {
  const m = viewProj;
  const x = m[0]! * p[0] + m[4]! * p[1] + m[8]! * p[2] + m[12]!;
  const y = m[1]! * p[0] + m[5]! * p[1] + m[9]! * p[2] + m[13]!;
  const w = m[3]! * p[0] + m[7]! * p[1] + m[11]! * p[2] + m[15]!;
  if (!(w > 0)) return null;
  return [((x / w + 1) / 2) * width, ((1 - y / w) / 2) * height];
}

/** The result of a screen-space pick. */
export interface Pick {
  readonly index: number;
  readonly distance: number;
}

/**
 * The point nearest the cursor on screen within `radius` pixels, or null.
 * Ties go to the lower index, so picking is deterministic.
 */
export function pickNearest(
  cursor: readonly [number, number],
  points: readonly Vec3[],
  viewProj: Mat4,
  width: number,
  height: number,
  radius: number,
): Pick | null {
  let best: Pick | null = null;
  points.forEach((p, index) => {
    const s = projectToScreen(p, viewProj, width, height);
    if (!s) return;
    const distance = Math.hypot(s[0] - cursor[0], s[1] - cursor[1]);
    if (distance <= radius && (best === null || distance < best.distance)) {
      best = { index, distance };
    }
  });
  return best;
}

/**
 * The sample of a polyline nearest the cursor on screen (for hover linking and
 * curve selection): index of the nearest vertex within `radius` pixels.
 */
export function pickPolyline(
  cursor: readonly [number, number],
  polyline: readonly Vec3[],
  viewProj: Mat4,
  width: number,
  height: number,
  radius: number,
): Pick | null {
  let best: Pick | null = null;
  let prev: [number, number] | null = null;
  polyline.forEach((p, index) => {
    const s = projectToScreen(p, viewProj, width, height);
    if (!s) {
      prev = null;
      return;
    }
    let distance = Math.hypot(s[0] - cursor[0], s[1] - cursor[1]);
    if (prev) {
      distance = Math.min(distance, segmentDistance(cursor, prev, s));
    }
    if (distance <= radius && (best === null || distance < best.distance)) {
      // Report the nearer endpoint of the segment as the sample.
      const a = prev;
      const nearerPrev =
        a !== null &&
        Math.hypot(a[0] - cursor[0], a[1] - cursor[1]) <
          Math.hypot(s[0] - cursor[0], s[1] - cursor[1]);
      best = { index: nearerPrev ? index - 1 : index, distance };
    }
    prev = s;
  });
  return best;
}

/** Distance in pixels from point c to the segment a–b. */
export function segmentDistance(
  c: readonly [number, number],
  a: readonly [number, number],
  b: readonly [number, number],
): number {
  const dx = b[0] - a[0];
  const dy = b[1] - a[1];
  const len2 = dx * dx + dy * dy;
  const t =
    len2 === 0 ? 0 : Math.max(0, Math.min(1, ((c[0] - a[0]) * dx + (c[1] - a[1]) * dy) / len2));
  return Math.hypot(c[0] - (a[0] + t * dx), c[1] - (a[1] + t * dy));
}

/**
 * Move a dragged point in the plane through it parallel to the view's working
 * plane: the point keeps its depth, follows the cursor in the view.
 */
export function dragPlane(view: ViewName, point: Vec3): WorkingPlane {
  const base = workingPlane(view);
  const depth = dot(sub(point, base.origin), base.normal);
  return { ...base, origin: add(base.origin, scale(base.normal, depth)) };
}

/** Axis-aligned bounds of a set of points, or null for none. */
export function bounds(points: Iterable<Vec3>): { min: Vec3; max: Vec3 } | null {
  let min: [number, number, number] | null = null;
  let max: [number, number, number] = [0, 0, 0];
  for (const p of points) {
    if (!min) {
      min = [p[0], p[1], p[2]];
      max = [p[0], p[1], p[2]];
      continue;
    }
    for (let k = 0; k < 3; k++) {
      min[k] = Math.min(min[k]!, p[k]!);
      max[k] = Math.max(max[k]!, p[k]!);
    }
  }
  return min ? { min, max } : null;
}

/** What object snap can land on: points (handles, end points) and polylines (curves as drawn). */
export interface SnapTargets {
  readonly points: readonly Vec3[];
  readonly polylines: readonly (readonly Vec3[])[];
}

/**
 * Object snap: the target point nearest the cursor on screen within `radius` pixels (points win
 * over curves: a handle or end point is what a designer aims at), else the nearest point of a
 * polyline within `radius` (the segment's closest point on screen, at the same fraction of the
 * segment in space: exact in the orthographic views, on the chord in perspective), else null.
 * Ties go to the first target, so a snap is deterministic. `index` is the point's or polyline's.
 */
export function snapToObjects(
  cursor: readonly [number, number],
  targets: SnapTargets,
  viewProj: Mat4,
  width: number,
  height: number,
  radius: number,
): { point: Vec3; kind: 'point' | 'curve'; index: number; distance: number } | null {
  const near = pickNearest(cursor, targets.points, viewProj, width, height, radius);
  if (near)
    return {
      point: targets.points[near.index]!,
      kind: 'point',
      index: near.index,
      distance: near.distance,
    };
  let best: { point: Vec3; kind: 'curve'; index: number; distance: number } | null = null;
  for (const [index, line] of targets.polylines.entries()) {
    let prev = line.length > 0 ? projectToScreen(line[0]!, viewProj, width, height) : null;
    for (let i = 1; i < line.length; i++) {
      const s = projectToScreen(line[i]!, viewProj, width, height);
      if (prev && s) {
        const dx = s[0] - prev[0];
        const dy = s[1] - prev[1];
        const len2 = dx * dx + dy * dy;
        const f =
          len2 === 0
            ? 0
            : Math.max(
                0,
                Math.min(1, ((cursor[0] - prev[0]) * dx + (cursor[1] - prev[1]) * dy) / len2),
              );
        const d = Math.hypot(prev[0] + f * dx - cursor[0], prev[1] + f * dy - cursor[1]);
        if (d <= radius && (!best || d < best.distance)) {
          const a = line[i - 1]!;
          best = { point: add(a, scale(sub(line[i]!, a), f)), kind: 'curve', index, distance: d };
        }
      }
      prev = s;
    }
  }
  return best;
}
