// The viewports of appendix 8.7: top, front, side (orthographic) and a 3-D
// perspective view sharing one scene and one WebGL canvas (scissored), with
// orbit, pan, zoom, fit-all, a grid per view and single or four-view layouts.
// Drawing only: every curve polyline, fin and frame comes from the server.

import * as THREE from 'three';
import type { Analysis, FinKind, Point } from '../api/types';
import {
  bounds,
  fromPlane,
  gridSpacing,
  toPlane,
  intersectPlane,
  snapToGrid,
  workingPlane,
  VIEW_NAMES,
  type Ray,
  type Vec3,
  type ViewName,
  type WorkingPlane,
} from './math';

export const FIN_COLOURS: Record<FinKind, number> = {
  curvature: 0xd64bd6,
  torsion: 0x3cbf5a,
  normal: 0xf28c28,
  binormal: 0x2bb5d6,
  'bishop-u': 0xe0c020,
  'bishop-v': 0x9a7fe0,
  combescure: 0xf25c54,
};

interface View {
  name: ViewName;
  camera: THREE.OrthographicCamera | THREE.PerspectiveCamera;
  el: HTMLElement;
  grid: THREE.GridHelper;
  gridStep: number;
  target: THREE.Vector3;
  /** Half-height of the orthographic view in world units. */
  halfHeight: number;
  rect: { x: number; y: number; w: number; h: number };
}

interface CurveView {
  curve: THREE.Line;
  polygon: THREE.Line;
  handles: THREE.Points;
  fins: THREE.LineSegments;
  frames: THREE.LineSegments;
}

export interface CurveDrawing {
  analysis: Analysis | undefined;
  /** Control points (or data points) drawn as handles with their polygon. */
  handles: readonly Vec3[];
  polygon: boolean;
  selected: boolean;
  fins: readonly FinKind[];
  /** Frenet frames (T, N, B from the server) drawn along the curve. */
  frames: boolean;
  /** The curve's own colour when not selected (the object list shows it). */
  colour: number;
  /** False: the curve and everything of it is hidden (object list). */
  visible: boolean;
}

const VIEW_LABELS: Record<ViewName, string> = {
  top: 'Top (X-Y)',
  front: 'Front (Z-X)',
  side: 'Side (Y-Z)',
  persp: '3-D',
};

export type Layout = 'quad' | 'single';

export class Viewports {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene = new THREE.Scene();
  readonly views: View[];
  layout: Layout = 'quad';
  active: ViewName = 'top';
  snap = false;
  private readonly curves = new Map<string, CurveView>();
  private readonly preview: THREE.Line;
  private readonly previewPoints: THREE.Points;
  private readonly marker: THREE.Mesh;
  /** The faint previous curve (before a drag or a rebuild), for comparison. */
  private readonly ghost: THREE.Line;
  private frameRequested = 0;
  /** Frames drawn so far (benchmarks) and callbacks after each frame. */
  frames = 0;
  readonly afterFrame = new Set<(time: number) => void>();
  /**
   * Callbacks at the start of each frame, before it is drawn: where a drag
   * updates the scene once per frame however many pointer events came.
   */
  readonly beforeFrame = new Set<(time: number) => void>();

  constructor(readonly root: HTMLElement) {
    this.renderer = makeRenderer();
    this.renderer.setPixelRatio(Math.min(2, window.devicePixelRatio));
    this.renderer.setScissorTest(true);
    this.renderer.domElement.className = 'viewport-canvas';
    this.renderer.domElement.setAttribute('aria-hidden', 'true');
    root.appendChild(this.renderer.domElement);
    this.scene.background = new THREE.Color(0x1d2128);
    this.views = VIEW_NAMES.map((name) => this.makeView(name));
    this.preview = new THREE.Line(
      new THREE.BufferGeometry(),
      new THREE.LineDashedMaterial({ color: 0x9fd3ff, dashSize: 1, gapSize: 0.5 }),
    );
    this.previewPoints = new THREE.Points(
      new THREE.BufferGeometry(),
      new THREE.PointsMaterial({ color: 0x9fd3ff, size: 7, sizeAttenuation: false }),
    );
    this.marker = new THREE.Mesh(
      new THREE.SphereGeometry(1, 12, 8),
      new THREE.MeshBasicMaterial({ color: 0xffe14d }),
    );
    this.marker.visible = false;
    this.ghost = new THREE.Line(
      new THREE.BufferGeometry(),
      new THREE.LineBasicMaterial({ color: 0xc8d2e0, transparent: true, opacity: 0.35 }),
    );
    this.ghost.visible = false;
    this.scene.add(this.preview, this.previewPoints, this.marker, this.ghost);
    new ResizeObserver(() => {
      this.resize();
    }).observe(root);
    this.resize();
  }

  private makeView(name: ViewName): View {
    const el = document.createElement('div');
    el.className = 'view';
    el.dataset['view'] = name;
    el.tabIndex = 0;
    el.setAttribute('role', 'application');
    el.setAttribute('aria-label', `${VIEW_LABELS[name]} viewport`);
    const label = document.createElement('span');
    label.className = 'view-label';
    label.textContent = VIEW_LABELS[name];
    el.appendChild(label);
    this.root.appendChild(el);
    const camera =
      name === 'persp'
        ? new THREE.PerspectiveCamera(40, 1, 0.01, 1e6)
        : new THREE.OrthographicCamera(-1, 1, 1, -1, -1e6, 1e6);
    camera.up.set(0, 0, 1);
    const plane = workingPlane(name);
    const grid = new THREE.GridHelper(1, 1, 0x3c4656, 0x2b323d);
    // GridHelper lies in X-Z; turn it into the view's working plane.
    // GridHelper lies in its local X-Z plane: X → u, Y → normal, Z → −v is a
    // proper rotation (determinant +1) onto the plane spanned by u and v.
    const m = new THREE.Matrix4().makeBasis(
      new THREE.Vector3(...plane.u),
      new THREE.Vector3(...plane.normal),
      new THREE.Vector3(...plane.v).negate(),
    );
    grid.quaternion.setFromRotationMatrix(m);
    grid.visible = false;
    this.scene.add(grid);
    const v: View = {
      name,
      camera,
      el,
      grid,
      gridStep: 0,
      target: new THREE.Vector3(60, 0, 0),
      halfHeight: 60,
      rect: { x: 0, y: 0, w: 1, h: 1 },
    };
    this.placeCamera(v, name === 'persp' ? new THREE.Vector3(160, -180, 140) : undefined);
    return v;
  }

  view(name: ViewName): View {
    return this.views.find((v) => v.name === name)!;
  }

  /** Position a view's camera around its target (orthographic views look along their normal). */
  private placeCamera(v: View, perspPosition?: THREE.Vector3): void {
    if (v.camera instanceof THREE.PerspectiveCamera) {
      if (perspPosition) v.camera.position.copy(perspPosition);
      v.camera.lookAt(v.target);
    } else {
      const n = workingPlane(v.name).normal;
      v.camera.position.set(
        v.target.x + n[0] * 1000,
        v.target.y + n[1] * 1000,
        v.target.z + n[2] * 1000,
      );
      v.camera.up.set(...workingPlane(v.name).v);
      v.camera.lookAt(v.target);
    }
    this.updateProjection(v);
  }

  private updateProjection(v: View): void {
    const aspect = v.rect.w / Math.max(1, v.rect.h);
    if (v.camera instanceof THREE.PerspectiveCamera) {
      v.camera.aspect = aspect;
    } else {
      v.camera.top = v.halfHeight;
      v.camera.bottom = -v.halfHeight;
      v.camera.left = -v.halfHeight * aspect;
      v.camera.right = v.halfHeight * aspect;
    }
    v.camera.updateProjectionMatrix();
    v.camera.updateMatrixWorld();
    this.updateGrid(v);
  }

  /** World units per pixel at the view's target. */
  worldPerPixel(v: View): number {
    if (v.camera instanceof THREE.PerspectiveCamera) {
      const d = v.camera.position.distanceTo(v.target);
      return (2 * d * Math.tan(THREE.MathUtils.degToRad(v.camera.fov / 2))) / Math.max(1, v.rect.h);
    }
    return (2 * v.halfHeight) / Math.max(1, v.rect.h);
  }

  private updateGrid(v: View): void {
    const step = gridSpacing(this.worldPerPixel(v), 16);
    const plane = workingPlane(v.name);
    const extent = Math.max(v.rect.w, v.rect.h) * this.worldPerPixel(v) * 1.5;
    const divisions = Math.min(400, Math.ceil(extent / step / 2) * 2);
    if (step !== v.gridStep || v.grid.userData['divisions'] !== divisions) {
      const old = v.grid;
      const grid = new THREE.GridHelper(divisions * step, divisions, 0x46526a, 0x2b323d);
      grid.quaternion.copy(old.quaternion);
      grid.userData['divisions'] = divisions;
      this.scene.remove(old);
      old.geometry.dispose();
      this.scene.add(grid);
      v.grid = grid;
      v.gridStep = step;
    }
    // Keep the grid centred on the target, on whole steps, inside the plane.
    const t: Vec3 = [v.target.x, v.target.y, v.target.z];
    const c = snapToGrid(t, plane, step);
    const depth = plane.normal[0] * c[0] + plane.normal[1] * c[1] + plane.normal[2] * c[2];
    v.grid.position.set(
      c[0] - plane.normal[0] * depth,
      c[1] - plane.normal[1] * depth,
      c[2] - plane.normal[2] * depth,
    );
  }

  gridStep(name: ViewName): number {
    return this.view(name).gridStep;
  }

  setLayout(layout: Layout, active?: ViewName): void {
    this.layout = layout;
    if (active) this.active = active;
    this.resize();
  }

  resize(): void {
    const w = this.root.clientWidth;
    const h = this.root.clientHeight;
    this.renderer.setSize(w, h, false);
    this.renderer.domElement.style.width = `${w}px`;
    this.renderer.domElement.style.height = `${h}px`;
    const hw = Math.floor(w / 2);
    const hh = Math.floor(h / 2);
    const quad: Record<ViewName, View['rect']> = {
      top: { x: 0, y: 0, w: hw, h: hh },
      persp: { x: hw, y: 0, w: w - hw, h: hh },
      front: { x: 0, y: hh, w: hw, h: h - hh },
      side: { x: hw, y: hh, w: w - hw, h: h - hh },
    };
    for (const v of this.views) {
      const show = this.layout === 'quad' || v.name === this.active;
      v.rect = this.layout === 'quad' ? quad[v.name] : { x: 0, y: 0, w, h };
      v.el.hidden = !show;
      Object.assign(v.el.style, {
        left: `${v.rect.x}px`,
        top: `${v.rect.y}px`,
        width: `${v.rect.w}px`,
        height: `${v.rect.h}px`,
      });
      v.el.classList.toggle('active', v.name === this.active);
      this.updateProjection(v);
    }
    this.requestRender();
  }

  requestRender(): void {
    if (this.frameRequested) return;
    this.frameRequested = requestAnimationFrame((time) => {
      // Still marked as requested: what the hooks change is drawn in this frame.
      for (const f of this.beforeFrame) f(time);
      this.frameRequested = 0;
      this.render();
      for (const f of this.afterFrame) f(time);
    });
  }

  get renderPending(): boolean {
    return this.frameRequested !== 0;
  }

  render(): void {
    const h = this.root.clientHeight;
    for (const v of this.views) {
      if (v.el.hidden) continue;
      const { x, y, w, h: vh } = v.rect;
      this.renderer.setViewport(x, h - y - vh, w, vh);
      this.renderer.setScissor(x, h - y - vh, w, vh);
      for (const o of this.views) o.grid.visible = o === v;
      this.marker.scale.setScalar(this.worldPerPixel(v) * 4);
      this.renderer.render(this.scene, v.camera);
    }
    this.frames++;
  }

  /** The ray through pixel (px, py) of a view (pixels relative to the view's box). */
  ray(name: ViewName, px: number, py: number): Ray {
    const v = this.view(name);
    const ndc = new THREE.Vector3((px / v.rect.w) * 2 - 1, 1 - (py / v.rect.h) * 2, -1);
    const far = ndc.clone().setZ(1);
    ndc.unproject(v.camera);
    far.unproject(v.camera);
    const d = far.sub(ndc);
    return { origin: [ndc.x, ndc.y, ndc.z], direction: [d.x, d.y, d.z] };
  }

  /** Column-major view-projection matrix of a view (for screen-space picking). */
  viewProj(name: ViewName): Float32Array | number[] {
    const c = this.view(name).camera;
    return new THREE.Matrix4().multiplyMatrices(c.projectionMatrix, c.matrixWorldInverse).elements;
  }

  size(name: ViewName): { w: number; h: number } {
    const r = this.view(name).rect;
    return { w: r.w, h: r.h };
  }

  /** The world point under the cursor on a plane, snapped to the view's grid when snapping is on. */
  pointOn(
    name: ViewName,
    px: number,
    py: number,
    plane: WorkingPlane,
    snap = this.snap,
  ): Vec3 | null {
    const hit = intersectPlane(this.ray(name, px, py), plane);
    if (!hit) return null;
    // Exactly on the plane (no rounding noise along the normal), then snapped in it.
    const [u, v] = toPlane(hit, plane);
    const onPlane = fromPlane(u, v, plane);
    return snap ? snapToGrid(onPlane, plane, this.view(name).gridStep) : onPlane;
  }

  /** A point on a plane, snapped to the view's grid when snapping is on. */
  snapped(name: ViewName, p: Vec3, plane: WorkingPlane): Vec3 {
    const [u, v] = toPlane(p, plane);
    const onPlane = fromPlane(u, v, plane);
    return this.snap ? snapToGrid(onPlane, plane, this.view(name).gridStep) : onPlane;
  }

  // ---- camera navigation -------------------------------------------------

  pan(name: ViewName, dxPx: number, dyPx: number): void {
    const v = this.view(name);
    const k = this.worldPerPixel(v);
    const right = new THREE.Vector3().setFromMatrixColumn(v.camera.matrixWorld, 0);
    const up = new THREE.Vector3().setFromMatrixColumn(v.camera.matrixWorld, 1);
    const delta = right.multiplyScalar(-dxPx * k).add(up.multiplyScalar(dyPx * k));
    v.target.add(delta);
    v.camera.position.add(delta);
    v.camera.updateMatrixWorld();
    this.updateGrid(v);
    this.requestRender();
  }

  zoom(name: ViewName, factor: number): void {
    const v = this.view(name);
    if (v.camera instanceof THREE.PerspectiveCamera) {
      const off = v.camera.position.clone().sub(v.target).multiplyScalar(factor);
      v.camera.position.copy(v.target).add(off);
      v.camera.updateMatrixWorld();
    } else {
      v.halfHeight *= factor;
    }
    this.updateProjection(v);
    this.requestRender();
  }

  /** Orbit the perspective view about its target (turntable about Z). */
  orbit(name: ViewName, dxPx: number, dyPx: number): void {
    const v = this.view(name);
    if (!(v.camera instanceof THREE.PerspectiveCamera)) return;
    const off = v.camera.position.clone().sub(v.target);
    const sph = new THREE.Spherical().setFromCartesianCoords(off.x, off.z, -off.y);
    sph.theta -= dxPx * 0.01;
    sph.phi = THREE.MathUtils.clamp(sph.phi - dyPx * 0.01, 0.05, Math.PI - 0.05);
    const c = new THREE.Vector3().setFromSpherical(sph);
    v.camera.position.set(v.target.x + c.x, v.target.y - c.z, v.target.z + c.y);
    v.camera.lookAt(v.target);
    v.camera.updateMatrixWorld();
    this.requestRender();
  }

  /** Fit every view to the given points (fit-all), with a margin. */
  fit(points: Iterable<Vec3>): void {
    const b = bounds(points);
    if (!b) return;
    const c = new THREE.Vector3(
      (b.min[0] + b.max[0]) / 2,
      (b.min[1] + b.max[1]) / 2,
      (b.min[2] + b.max[2]) / 2,
    );
    const size = Math.max(b.max[0] - b.min[0], b.max[1] - b.min[1], b.max[2] - b.min[2], 1e-3);
    for (const v of this.views) {
      const dir =
        v.camera instanceof THREE.PerspectiveCamera
          ? v.camera.position.clone().sub(v.target).normalize()
          : null;
      v.target.copy(c);
      v.halfHeight = size * 0.65;
      if (v.camera instanceof THREE.PerspectiveCamera && dir) {
        const dist = (size * 0.8) / Math.tan(THREE.MathUtils.degToRad(v.camera.fov / 2));
        v.camera.position.copy(c).add(dir.multiplyScalar(dist));
        this.placeCamera(v);
      } else {
        this.placeCamera(v);
      }
    }
    this.requestRender();
  }

  // ---- scene content -----------------------------------------------------

  private curveView(label: string): CurveView {
    let cv = this.curves.get(label);
    if (!cv) {
      cv = {
        curve: new THREE.Line(
          new THREE.BufferGeometry(),
          new THREE.LineBasicMaterial({ color: 0xe8ecf1 }),
        ),
        polygon: new THREE.Line(
          new THREE.BufferGeometry(),
          new THREE.LineBasicMaterial({ color: 0x7d8ca3 }),
        ),
        handles: new THREE.Points(
          new THREE.BufferGeometry(),
          new THREE.PointsMaterial({ color: 0xffffff, size: 8, sizeAttenuation: false }),
        ),
        fins: new THREE.LineSegments(
          new THREE.BufferGeometry(),
          new THREE.LineBasicMaterial({ vertexColors: true }),
        ),
        frames: new THREE.LineSegments(
          new THREE.BufferGeometry(),
          new THREE.LineBasicMaterial({ vertexColors: true }),
        ),
      };
      cv.curve.userData['label'] = label;
      this.scene.add(cv.curve, cv.polygon, cv.handles, cv.fins, cv.frames);
      this.curves.set(label, cv);
    }
    return cv;
  }

  /** The colour a curve's line is drawn in now (the selection's blue when selected): for inspection and tests. */
  drawnColour(label: string): number | undefined {
    return (
      this.curves.get(label)?.curve.material as THREE.LineBasicMaterial | undefined
    )?.color.getHex();
  }

  /** Draw one curve from its server analysis and its handles. */
  drawCurve(label: string, d: CurveDrawing): void {
    const cv = this.curveView(label);
    const a = d.analysis;
    setPositions(cv.curve.geometry, a ? a.points : []);
    (cv.curve.material as THREE.LineBasicMaterial).color.set(d.selected ? 0x4da3ff : d.colour);
    cv.curve.visible = d.visible;
    cv.fins.visible = d.visible;
    cv.frames.visible = d.visible;
    setPositions(cv.polygon.geometry, d.polygon ? d.handles : []);
    setPositions(cv.handles.geometry, d.selected ? d.handles : []);
    cv.polygon.visible = d.visible && d.polygon && d.selected;
    cv.handles.visible = d.visible && d.selected;
    // Fins: every polyline of every requested kind, as segments in the kind's colour.
    const segs = new Segments(cv.fins.geometry);
    for (const kind of d.fins) {
      const lines = a?.fins[kind] ?? [];
      const col = new THREE.Color(FIN_COLOURS[kind]);
      for (const line of lines) segs.strip(line, col);
    }
    segs.done();
    // Frames: short T (red), N (green), B (blue) axes every few samples.
    const fsegs = new Segments(cv.frames.geometry);
    const frames = d.frames ? a?.frames : undefined;
    if (a && frames && frames.length === a.points.length) {
      const b = bounds(a.points.map(toVec3));
      const len = b ? 0.06 * Math.max(...b.max.map((m, i) => m - b.min[i]!)) : 1;
      const every = Math.max(1, Math.floor(a.points.length / 24));
      const axisCols = [
        new THREE.Color(0xe05555),
        new THREE.Color(0x55e07a),
        new THREE.Color(0x5599ff),
      ];
      for (let i = 0; i < a.points.length; i += every) {
        const p = toVec3(a.points[i]!);
        const f = frames[i]!;
        [f.T, f.N, f.B].forEach((axis, k) => {
          if (!axis.every(Number.isFinite)) return;
          const q = toVec3(axis);
          fsegs.strip([p, [p[0] + q[0] * len, p[1] + q[1] * len, p[2] + q[2] * len]], axisCols[k]!);
        });
      }
    }
    fsegs.done();
    this.requestRender();
  }

  /**
   * The fin segments in the scene for a curve, read back from its geometry
   * with their colour (FIN_COLOURS): what is drawn, for inspection and tests.
   */
  finSegments(label: string): { from: Vec3; to: Vec3; colour: number }[] {
    const g = this.curves.get(label)?.fins.geometry;
    const pos = g?.getAttribute('position');
    const col = g?.getAttribute('color');
    if (!g || !pos || !col) return [];
    const out: { from: Vec3; to: Vec3; colour: number }[] = [];
    // The buffers are reused and may be longer than what is drawn: only the draw range counts.
    const drawn = Math.min(pos.count, g.drawRange.count);
    for (let i = 0; i + 1 < drawn; i += 2)
      out.push({
        from: [pos.getX(i), pos.getY(i), pos.getZ(i)],
        to: [pos.getX(i + 1), pos.getY(i + 1), pos.getZ(i + 1)],
        colour: new THREE.Color(col.getX(i), col.getY(i), col.getZ(i)).getHex(),
      });
    return out;
  }

  removeCurve(label: string): void {
    const cv = this.curves.get(label);
    if (!cv) return;
    for (const o of [cv.curve, cv.polygon, cv.handles, cv.fins, cv.frames]) {
      this.scene.remove(o);
      o.geometry.dispose();
    }
    this.curves.delete(label);
    this.requestRender();
  }

  /**
   * Rubber-band preview of the tool being used (points entered so far), or a
   * candidate curve (its polyline) with its data points as `markers`.
   */
  setPreview(points: readonly Vec3[], markers: readonly Vec3[] = points): void {
    setPositions(this.preview.geometry, points);
    this.preview.computeLineDistances();
    setPositions(this.previewPoints.geometry, markers);
    this.root.dataset['preview'] = points.length ? String(points.length) : '';
    this.requestRender();
  }

  /** Show the ghost polyline (the curve as it was), or hide it. */
  setGhost(points: readonly Point[] | null): void {
    this.ghost.visible = points !== null && points.length > 1;
    if (points) setPositions(this.ghost.geometry, points);
    this.root.dataset['ghost'] = this.ghost.visible ? String(points!.length) : '';
    this.requestRender();
  }

  /** The fairing assistant's ghost (curve and curvature comb), made on first use. */
  private faired: { curve: THREE.Line; comb: THREE.LineSegments } | null = null;

  /** Show the fairing assistant's ghost: the faired curve and its comb polylines, or hide it. */
  setFaired(points: readonly Point[] | null, comb: readonly (readonly Point[])[] = []): void {
    if (!this.faired) {
      this.faired = {
        curve: new THREE.Line(
          new THREE.BufferGeometry(),
          new THREE.LineDashedMaterial({ color: 0x7fe3a0, dashSize: 2, gapSize: 1 }),
        ),
        comb: new THREE.LineSegments(
          new THREE.BufferGeometry(),
          new THREE.LineBasicMaterial({ vertexColors: true, transparent: true, opacity: 0.6 }),
        ),
      };
      this.scene.add(this.faired.curve, this.faired.comb);
    }
    const shown = points !== null && points.length > 1;
    this.faired.curve.visible = shown;
    this.faired.comb.visible = shown;
    if (shown) {
      setPositions(this.faired.curve.geometry, points);
      this.faired.curve.computeLineDistances();
      const segs = new Segments(this.faired.comb.geometry);
      const col = new THREE.Color(0x7fe3a0);
      for (const line of comb) segs.strip(line, col);
      segs.done();
    }
    this.root.dataset['faired'] = shown ? String(points.length) : '';
    this.requestRender();
  }

  /** The linked-hover marker (graph ↔ curve), or none. */
  setMarker(p: Vec3 | null): void {
    this.marker.visible = p !== null;
    if (p) this.marker.position.set(p[0], p[1], p[2]);
    this.requestRender();
  }

  get markerPosition(): Vec3 | null {
    return this.marker.visible
      ? [this.marker.position.x, this.marker.position.y, this.marker.position.z]
      : null;
  }
}

export function toVec3(p: readonly number[]): Vec3 {
  return [p[0] ?? 0, p[1] ?? 0, p[2] ?? 0];
}

function setPositions(g: THREE.BufferGeometry, pts: readonly (Point | Vec3)[]): void {
  const n = pts.length;
  let attr = g.getAttribute('position') as THREE.BufferAttribute | undefined;
  if (!attr || attr.count < n || attr.count > 4 * n + 16) {
    attr = new THREE.BufferAttribute(new Float32Array(Math.max(n, 1) * 3), 3);
    attr.setUsage(THREE.DynamicDrawUsage);
    g.setAttribute('position', attr);
  }
  const arr = attr.array as Float32Array;
  for (let i = 0; i < n; i++) {
    const p = toVec3(pts[i]!);
    arr[3 * i] = p[0];
    arr[3 * i + 1] = p[1];
    arr[3 * i + 2] = p[2];
  }
  attr.needsUpdate = true;
  g.setDrawRange(0, n);
  g.computeBoundingSphere();
}

/**
 * Line segments written into a geometry's own position and colour buffers,
 * which are kept and grown by doubling (no allocation per redraw of a drag).
 */
class Segments {
  private pos: Float32Array;
  private col: Float32Array;
  private n = 0;

  constructor(private readonly g: THREE.BufferGeometry) {
    const p = g.getAttribute('position') as THREE.BufferAttribute | undefined;
    const c = g.getAttribute('color') as THREE.BufferAttribute | undefined;
    this.pos = p && c ? (p.array as Float32Array) : new Float32Array(0);
    this.col = p && c ? (c.array as Float32Array) : new Float32Array(0);
  }

  /** The segments of a polyline (those with a non-finite end are skipped). */
  strip(line: readonly (Point | Vec3)[], c: THREE.Color): void {
    for (let i = 0; i + 1 < line.length; i++) {
      const a: readonly number[] = line[i]!;
      const b: readonly number[] = line[i + 1]!;
      const ax = a[0] ?? 0,
        ay = a[1] ?? 0,
        az = a[2] ?? 0,
        bx = b[0] ?? 0,
        by = b[1] ?? 0,
        bz = b[2] ?? 0;
      if (!Number.isFinite(ax + ay + az + bx + by + bz)) continue;
      if (6 * (this.n + 2) > this.pos.length) this.grow();
      const k = 3 * this.n;
      const pos = this.pos;
      const col = this.col;
      pos[k] = ax;
      pos[k + 1] = ay;
      pos[k + 2] = az;
      pos[k + 3] = bx;
      pos[k + 4] = by;
      pos[k + 5] = bz;
      for (let j = 0; j < 6; j += 3) {
        col[k + j] = c.r;
        col[k + j + 1] = c.g;
        col[k + j + 2] = c.b;
      }
      this.n += 2;
    }
  }

  private grow(): void {
    const size = Math.max(96, 2 * this.pos.length);
    const pos = new Float32Array(size);
    const col = new Float32Array(size);
    pos.set(this.pos.subarray(0, 3 * this.n));
    col.set(this.col.subarray(0, 3 * this.n));
    this.pos = pos;
    this.col = col;
  }

  /** Hand the buffers to the geometry (new attributes only when they grew). */
  done(): void {
    const p = this.g.getAttribute('position') as THREE.BufferAttribute | undefined;
    if (p?.array === this.pos) {
      p.needsUpdate = true;
      (this.g.getAttribute('color') as THREE.BufferAttribute).needsUpdate = true;
    } else {
      const pa = new THREE.BufferAttribute(this.pos, 3);
      const ca = new THREE.BufferAttribute(this.col, 3);
      pa.setUsage(THREE.DynamicDrawUsage);
      ca.setUsage(THREE.DynamicDrawUsage);
      this.g.setAttribute('position', pa);
      this.g.setAttribute('color', ca);
    }
    this.g.setDrawRange(0, this.n);
    this.g.computeBoundingSphere();
  }
}

/**
 * The WebGL renderer: antialiased on a GPU; without multisampling when the
 * browser renders WebGL in software (SwiftShader, llvmpipe: the headless e2e
 * runs), where multisampling doubled the cost of every frame
 * (docs/benchmarks.md). A 1×1 probe context names the renderer.
 */
function makeRenderer(): THREE.WebGLRenderer {
  return new THREE.WebGLRenderer({ antialias: !softwareWebGL() });
}

function softwareWebGL(): boolean {
  const gl = document.createElement('canvas').getContext('webgl2', { antialias: false });
  if (!gl) return false;
  const info = gl.getExtension('WEBGL_debug_renderer_info');
  const name = String(gl.getParameter(info ? info.UNMASKED_RENDERER_WEBGL : gl.RENDERER));
  gl.getExtension('WEBGL_lose_context')?.loseContext();
  return /swiftshader|llvmpipe|softpipe|software/i.test(name);
}
