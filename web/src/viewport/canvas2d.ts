// The views drawn with the 2-D canvas where WebGL runs in software (headless
// chromium with --disable-gpu: SwiftShader; llvmpipe), in place of three.js's
// WebGLRenderer. The scene is the same three.js scene (cameras, curves, fins,
// grids, handles, ghosts); this draws what it holds: lines, line segments
// (vertex colours), dashed lines, points (squares of the material's size in
// pixels) and meshes (a disc of the mesh's bounding sphere: the hover
// marker), in scene order, transparent objects after the others, with no
// depth test (every object is a line or a point).
//
// Why (docs/benchmarks.md, "The views on the 2-D canvas"): a software WebGL
// frame costs the GPU process ≈ 11 ms of SwiftShader and blocks the page's
// main thread while the frame is read back for the software compositor; the
// 2-D canvas of the same lines is rasterised in the page in ≈ 1 ms, with no
// read-back. On a GPU the WebGLRenderer stays.

import * as THREE from 'three';

/** The part of CanvasRenderingContext2D this renderer uses. */
export type Context2D = Pick<
  CanvasRenderingContext2D,
  | 'save'
  | 'restore'
  | 'beginPath'
  | 'rect'
  | 'clip'
  | 'fillRect'
  | 'moveTo'
  | 'lineTo'
  | 'stroke'
  | 'arc'
  | 'fill'
  | 'fillStyle'
  | 'strokeStyle'
  | 'lineWidth'
  | 'globalAlpha'
>;

/** The canvas drawn into (an HTMLCanvasElement in the page). */
export interface Canvas2D {
  width: number;
  height: number;
  readonly style: { width: string; height: string };
  getContext(kind: '2d'): Context2D | null;
}

interface Rect {
  x: number;
  y: number;
  w: number;
  h: number;
}

/**
 * The renderer's surface Viewports uses (as THREE.WebGLRenderer's): size,
 * pixel ratio, viewport and scissor (CSS pixels, origin at the bottom left,
 * as in WebGL) and render(scene, camera), which clears the scissor box to the
 * scene's background and draws the scene seen by the camera into the viewport.
 */
export class Canvas2DRenderer<C extends Canvas2D = Canvas2D> {
  private readonly ctx: Context2D;
  private ratio = 1;
  private viewport: Rect = { x: 0, y: 0, w: 1, h: 1 };
  private scissor: Rect = { x: 0, y: 0, w: 1, h: 1 };
  private scissorTest = false;
  private readonly m = new THREE.Matrix4();
  private readonly vp = new THREE.Matrix4();
  private readonly colour = new THREE.Color();
  private readonly sphere = new THREE.Sphere();

  constructor(readonly domElement: C) {
    const ctx = domElement.getContext('2d');
    if (!ctx) throw new Error('the 2-D canvas is not available');
    this.ctx = ctx;
  }

  setPixelRatio(ratio: number): void {
    this.ratio = ratio;
  }

  setSize(w: number, h: number, updateStyle = true): void {
    this.domElement.width = Math.floor(w * this.ratio);
    this.domElement.height = Math.floor(h * this.ratio);
    if (updateStyle) {
      this.domElement.style.width = `${w}px`;
      this.domElement.style.height = `${h}px`;
    }
  }

  setViewport(x: number, y: number, w: number, h: number): void {
    this.viewport = { x, y, w, h };
  }

  setScissor(x: number, y: number, w: number, h: number): void {
    this.scissor = { x, y, w, h };
  }

  setScissorTest(on: boolean): void {
    this.scissorTest = on;
  }

  render(scene: THREE.Scene, camera: THREE.Camera): void {
    const ctx = this.ctx;
    const r = this.ratio;
    const H = this.domElement.height;
    scene.updateMatrixWorld();
    if (camera.parent === null) camera.updateMatrixWorld();
    this.vp.multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
    ctx.save();
    const box = this.scissorTest
      ? this.scissor
      : { x: 0, y: 0, w: this.domElement.width / r, h: H / r };
    ctx.beginPath();
    ctx.rect(box.x * r, H - (box.y + box.h) * r, box.w * r, box.h * r);
    ctx.clip();
    if (scene.background instanceof THREE.Color) {
      ctx.fillStyle = `#${scene.background.getHexString()}`;
      ctx.fillRect(box.x * r, H - (box.y + box.h) * r, box.w * r, box.h * r);
    }
    const v = this.viewport;
    const view = { x: v.x * r, y: H - (v.y + v.h) * r, w: v.w * r, h: v.h * r };
    const later: THREE.Object3D[] = [];
    scene.traverseVisible((o) => {
      const mat = materialOf(o);
      if (!mat) return;
      if (mat.transparent) later.push(o);
      else this.draw(o, mat, view, camera);
    });
    for (const o of later) this.draw(o, materialOf(o)!, view, camera);
    ctx.restore();
  }

  private draw(o: THREE.Object3D, mat: THREE.Material, view: Rect, camera: THREE.Camera): void {
    const ctx = this.ctx;
    const g = geometryOf(o);
    const pos = g?.getAttribute('position');
    if (!g || !pos) return;
    this.m.multiplyMatrices(this.vp, o.matrixWorld);
    const e = this.m.elements;
    ctx.globalAlpha = mat.transparent ? mat.opacity : 1;
    ctx.lineWidth = 1;
    const plain = `#${colourOf(mat).getHexString()}`;
    const start = Math.max(0, g.drawRange.start);
    const end = Math.min(pos.count, start + g.drawRange.count);
    const idx = g.getIndex();
    if (o instanceof THREE.Points) {
      // WebGL points: squares of the material's size in device pixels, centred on the point.
      const size = (mat instanceof THREE.PointsMaterial ? mat.size : 1) * this.ratio;
      ctx.fillStyle = plain;
      for (let i = start; i < end; i++) {
        const p = projectPoint(e, pos.getX(i), pos.getY(i), pos.getZ(i), view);
        if (p) ctx.fillRect(p[0] - size / 2, p[1] - size / 2, size, size);
      }
    } else if (o instanceof THREE.Line) {
      const pairs = o instanceof THREE.LineSegments;
      const col = mat.vertexColors ? g.getAttribute('color') : undefined;
      const dashed = mat instanceof THREE.LineDashedMaterial ? mat : null;
      const dist = dashed ? g.getAttribute('lineDistance') : undefined;
      let style = '';
      let r = NaN,
        gr = NaN,
        bl = NaN;
      const n = idx ? Math.min(idx.count, start + g.drawRange.count) : end;
      const at = (k: number): number => (idx ? idx.getX(k) : k);
      const step = pairs ? 2 : 1;
      ctx.beginPath();
      for (let k = start; k + 1 < n; k += step) {
        const a = at(k);
        const b = at(k + 1);
        if (col && (col.getX(a) !== r || col.getY(a) !== gr || col.getZ(a) !== bl)) {
          r = col.getX(a);
          gr = col.getY(a);
          bl = col.getZ(a);
          const s = `#${this.colour.setRGB(r, gr, bl).getHexString()}`;
          if (s !== style) {
            if (style) ctx.stroke();
            ctx.beginPath();
            ctx.strokeStyle = style = s;
          }
        } else if (!col && !style) ctx.strokeStyle = style = plain;
        const seg = clipSegment(e, pos, a, b, view);
        if (!seg) continue;
        if (dashed && dist) {
          dashes(
            ctx,
            seg,
            dist.getX(a),
            dist.getX(b),
            dashed.dashSize,
            dashed.gapSize,
            dashed.scale,
          );
        } else {
          ctx.moveTo(seg[0], seg[1]);
          ctx.lineTo(seg[2], seg[3]);
        }
      }
      if (style) ctx.stroke();
    } else if (o instanceof THREE.Mesh) {
      // A disc of the mesh's bounding sphere (the hover marker, a small sphere).
      if (!g.boundingSphere) g.computeBoundingSphere();
      this.sphere.copy(g.boundingSphere!).applyMatrix4(o.matrixWorld);
      const c = this.sphere.center;
      const centre = projectPoint(this.vp.elements, c.x, c.y, c.z, view);
      const up = new THREE.Vector3().setFromMatrixColumn(camera.matrixWorld, 1);
      const rim = up.multiplyScalar(this.sphere.radius).add(c);
      const edge = projectPoint(this.vp.elements, rim.x, rim.y, rim.z, view);
      if (centre && edge) {
        ctx.fillStyle = plain;
        ctx.beginPath();
        ctx.arc(centre[0], centre[1], Math.hypot(edge[0] - centre[0], edge[1] - centre[1]), 0, 7);
        ctx.fill();
      }
    }
  }
}

/** The single material of a drawable object (line, points, mesh), or null. */
function materialOf(o: THREE.Object3D): THREE.Material | null {
  const m: unknown = (o as { material?: unknown }).material;
  return m instanceof THREE.Material ? m : null;
}

function geometryOf(o: THREE.Object3D): THREE.BufferGeometry | null {
  const g: unknown = (o as { geometry?: unknown }).geometry;
  return g instanceof THREE.BufferGeometry ? g : null;
}

const WHITE = new THREE.Color(0xffffff);

/** A material's colour (line, points and basic mesh materials have one). */
function colourOf(m: THREE.Material): THREE.Color {
  const c: unknown = (m as { color?: unknown }).color;
  return c instanceof THREE.Color ? c : WHITE;
}

/**
 * A point through the column-major matrix `e` (projection × view × model) to
 * canvas pixels of the viewport `view` (origin at the top left), or null
 * behind the camera (clip-space z < −w, in front of the near plane).
 */
export function projectPoint(
  e: ArrayLike<number>,
  x: number,
  y: number,
  z: number,
  view: Rect,
): [number, number] | null {
  const cx = e[0]! * x + e[4]! * y + e[8]! * z + e[12]!;
  const cy = e[1]! * x + e[5]! * y + e[9]! * z + e[13]!;
  const cz = e[2]! * x + e[6]! * y + e[10]! * z + e[14]!;
  const w = e[3]! * x + e[7]! * y + e[11]! * z + e[15]!;
  if (w <= 0 || cz < -w) return null;
  return [view.x + ((cx / w + 1) / 2) * view.w, view.y + ((1 - cy / w) / 2) * view.h];
}

/**
 * The segment between vertices a and b of `pos` in canvas pixels, clipped at
 * the camera's near plane (clip-space z ≥ −w), or null when wholly behind it.
 */
export function clipSegment(
  e: ArrayLike<number>,
  pos: THREE.BufferAttribute | THREE.InterleavedBufferAttribute,
  a: number,
  b: number,
  view: Rect,
): [number, number, number, number] | null {
  const clip = (i: number): [number, number, number, number] => {
    const x = pos.getX(i),
      y = pos.getY(i),
      z = pos.getZ(i);
    return [
      e[0]! * x + e[4]! * y + e[8]! * z + e[12]!,
      e[1]! * x + e[5]! * y + e[9]! * z + e[13]!,
      e[2]! * x + e[6]! * y + e[10]! * z + e[14]!,
      e[3]! * x + e[7]! * y + e[11]! * z + e[15]!,
    ];
  };
  let p = clip(a);
  let q = clip(b);
  if (![...p, ...q].every(Number.isFinite)) return null;
  // Distance to the near plane z = −w: in front where z + w ≥ 0.
  const dp = p[2] + p[3];
  const dq = q[2] + q[3];
  if (dp < 0 && dq < 0) return null;
  const cut = (u: number[], w: number[], t: number): [number, number, number, number] => [
    u[0]! + t * (w[0]! - u[0]!),
    u[1]! + t * (w[1]! - u[1]!),
    u[2]! + t * (w[2]! - u[2]!),
    u[3]! + t * (w[3]! - u[3]!),
  ];
  if (dp < 0) p = cut(p, q, dp / (dp - dq));
  else if (dq < 0) q = cut(q, p, dq / (dq - dp));
  if (p[3] <= 0 || q[3] <= 0) return null;
  const px = (c: number[]): number => view.x + ((c[0]! / c[3]! + 1) / 2) * view.w;
  const py = (c: number[]): number => view.y + ((1 - c[1]! / c[3]!) / 2) * view.h;
  return [px(p), py(p), px(q), py(q)];
}

/**
 * The dashes of a segment whose ends lie at distances da and db along the
 * line (three.js's lineDistance): drawn where the distance × scale modulo
 * (dash + gap) is below dash, as LineDashedMaterial draws them.
 */
function dashes(
  ctx: Context2D,
  seg: [number, number, number, number],
  da: number,
  db: number,
  dash: number,
  gap: number,
  scale: number,
): void {
  const period = dash + gap;
  const a = da * scale;
  const b = db * scale;
  const len = b - a;
  if (!(period > 0) || !(Math.abs(len) > 0)) {
    ctx.moveTo(seg[0], seg[1]);
    ctx.lineTo(seg[2], seg[3]);
    return;
  }
  const lo = Math.min(a, b);
  const hi = Math.max(a, b);
  const at = (d: number): [number, number] => {
    const t = (d - a) / len;
    return [seg[0] + t * (seg[2] - seg[0]), seg[1] + t * (seg[3] - seg[1])];
  };
  // At most a few hundred dashes per segment (a dash far below a pixel draws the segment whole).
  if ((hi - lo) / period > 512) {
    ctx.moveTo(seg[0], seg[1]);
    ctx.lineTo(seg[2], seg[3]);
    return;
  }
  for (let d0 = Math.floor(lo / period) * period; d0 < hi; d0 += period) {
    const s = Math.max(lo, d0);
    const t = Math.min(hi, d0 + dash);
    if (t <= s) continue;
    const [x0, y0] = at(s);
    const [x1, y1] = at(t);
    ctx.moveTo(x0, y0);
    ctx.lineTo(x1, y1);
  }
}
