import { describe, expect, it } from 'vitest';
import * as THREE from 'three';
import { Canvas2DRenderer, type Canvas2D } from './canvas2d';

/** A 2-D context that records what is drawn (the node test environment has no canvas). */
class Recorder {
  ops: (string | number)[][] = [];
  fillStyle = '';
  strokeStyle = '';
  lineWidth = 1;
  globalAlpha = 1;
  save(): void {}
  restore(): void {}
  beginPath(): void {
    this.ops.push(['begin']);
  }
  rect(x: number, y: number, w: number, h: number): void {
    this.ops.push(['rect', x, y, w, h]);
  }
  clip(): void {}
  fillRect(x: number, y: number, w: number, h: number): void {
    this.ops.push(['fillRect', this.fillStyle, x, y, w, h]);
  }
  moveTo(x: number, y: number): void {
    this.ops.push(['moveTo', x, y]);
  }
  lineTo(x: number, y: number): void {
    this.ops.push(['lineTo', x, y]);
  }
  stroke(): void {
    this.ops.push(['stroke', this.strokeStyle, this.globalAlpha]);
  }
  arc(x: number, y: number, r: number): void {
    this.ops.push(['arc', x, y, r]);
  }
  fill(): void {
    this.ops.push(['fill', this.fillStyle]);
  }
}

function setup(w = 400, h = 300, ratio = 1): { r: Canvas2DRenderer; rec: Recorder } {
  const rec = new Recorder();
  const canvas: Canvas2D = {
    width: 0,
    height: 0,
    style: { width: '', height: '' },
    getContext: () => rec,
  };
  const r = new Canvas2DRenderer(canvas);
  r.setPixelRatio(ratio);
  r.setSize(w, h, false);
  r.setViewport(0, 0, w, h);
  r.setScissor(0, 0, w, h);
  r.setScissorTest(true);
  return { r, rec };
}

/** three.js's own mapping of a world point to canvas pixels (top-left origin) of a w × h viewport. */
function reference(p: THREE.Vector3, cam: THREE.Camera, w: number, h: number): [number, number] {
  const n = p.clone().project(cam);
  return [((n.x + 1) / 2) * w, ((1 - n.y) / 2) * h];
}

function topCamera(): THREE.OrthographicCamera {
  const cam = new THREE.OrthographicCamera(-40, 40, 30, -30, -1e6, 1e6);
  cam.position.set(5, -3, 1000);
  cam.up.set(0, 1, 0);
  cam.lookAt(5, -3, 0);
  cam.updateMatrixWorld();
  return cam;
}

describe('the 2-D canvas renderer', () => {
  it('puts line vertices where three.js projects them, in the material colour', () => {
    const { r, rec } = setup();
    const cam = topCamera();
    const pts = [
      new THREE.Vector3(0, 0, 0),
      new THREE.Vector3(12, 7, 0),
      new THREE.Vector3(-20, 9, 3),
    ];
    const line = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(pts),
      new THREE.LineBasicMaterial({ color: 0x4da3ff }),
    );
    line.position.set(1, 2, 0); // the object's own transform counts
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0x1d2128);
    scene.add(line);
    r.render(scene, cam);
    expect(rec.ops).toContainEqual(['fillRect', '#1d2128', 0, 0, 400, 300]);
    const drawn = rec.ops.filter((o) => o[0] === 'moveTo' || o[0] === 'lineTo');
    expect(drawn).toHaveLength(4); // two segments
    const world = pts.map((p) => p.clone().add(new THREE.Vector3(1, 2, 0)));
    const want = [world[0]!, world[1]!, world[1]!, world[2]!].map((p) =>
      reference(p, cam, 400, 300),
    );
    drawn.forEach((o, i) => {
      expect(o[1]).toBeCloseTo(want[i]![0], 9);
      expect(o[2]).toBeCloseTo(want[i]![1], 9);
    });
    expect(rec.ops).toContainEqual(['stroke', '#4da3ff', 1]);
  });

  it('strokes vertex-coloured segments per colour run, within the draw range', () => {
    const { r, rec } = setup();
    const cam = topCamera();
    const pos = new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 2, 0, 5, 5, 0, 6, 6, 0]);
    const red = new THREE.Color(0xd64bd6);
    const green = new THREE.Color(0x3cbf5a);
    const col = new Float32Array(18);
    [red, red, red, red, green, green].forEach((c, i) => {
      col.set([c.r, c.g, c.b], 3 * i);
    });
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(pos, 3));
    g.setAttribute('color', new THREE.BufferAttribute(col, 3));
    const segs = new THREE.LineSegments(g, new THREE.LineBasicMaterial({ vertexColors: true }));
    const scene = new THREE.Scene();
    scene.add(segs);
    r.render(scene, cam);
    expect(rec.ops.filter((o) => o[0] === 'stroke')).toEqual([
      ['stroke', '#d64bd6', 1],
      ['stroke', '#3cbf5a', 1],
    ]);
    expect(rec.ops.filter((o) => o[0] === 'moveTo')).toHaveLength(3);
    // Only the first two segments are in the draw range: one stroke, the fin colour's.
    rec.ops = [];
    g.setDrawRange(0, 4);
    r.render(scene, cam);
    expect(rec.ops.filter((o) => o[0] === 'stroke')).toEqual([['stroke', '#d64bd6', 1]]);
    expect(rec.ops.filter((o) => o[0] === 'moveTo')).toHaveLength(2);
  });

  it('draws points as squares of the material size in device pixels, hidden objects not', () => {
    const { r, rec } = setup(400, 300, 2);
    const cam = topCamera();
    const p = new THREE.Vector3(3, 4, 0);
    const pts = new THREE.Points(
      new THREE.BufferGeometry().setFromPoints([p]),
      new THREE.PointsMaterial({ color: 0xffffff, size: 8, sizeAttenuation: false }),
    );
    const hidden = pts.clone();
    hidden.visible = false;
    const scene = new THREE.Scene();
    scene.add(pts, hidden);
    r.render(scene, cam);
    const [x, y] = reference(p, cam, 800, 600);
    const squares = rec.ops.filter((o) => o[0] === 'fillRect' && o[1] === '#ffffff');
    expect(squares).toHaveLength(1);
    const sq = squares[0]!;
    expect(sq[2]).toBeCloseTo(x - 8, 9);
    expect(sq[3]).toBeCloseTo(y - 8, 9);
    expect(sq.slice(4)).toEqual([16, 16]);
  });

  it('clips a segment at the perspective camera’s near plane and drops one behind it', () => {
    const { r, rec } = setup();
    const cam = new THREE.PerspectiveCamera(40, 4 / 3, 1, 1000);
    cam.position.set(0, 0, 10);
    cam.lookAt(0, 0, 0);
    cam.updateMatrixWorld();
    // From in front of the camera (z = 0) to behind it (z = 20); and one wholly behind.
    const line = new THREE.LineSegments(
      new THREE.BufferGeometry().setFromPoints([
        new THREE.Vector3(2, 1, 0),
        new THREE.Vector3(2, 1, 20),
        new THREE.Vector3(0, 0, 15),
        new THREE.Vector3(1, 1, 30),
      ]),
      new THREE.LineBasicMaterial({ color: 0xffffff }),
    );
    const scene = new THREE.Scene();
    scene.add(line);
    r.render(scene, cam);
    const drawn = rec.ops.filter((o) => o[0] === 'moveTo' || o[0] === 'lineTo');
    expect(drawn).toHaveLength(2);
    // The cut is where the segment meets the near plane, 1 in front of the camera: z = 9.
    const near = reference(new THREE.Vector3(2, 1, 9), cam, 400, 300);
    const start = reference(new THREE.Vector3(2, 1, 0), cam, 400, 300);
    expect(drawn[0]![1]).toBeCloseTo(start[0], 6);
    expect(drawn[0]![2]).toBeCloseTo(start[1], 6);
    expect(drawn[1]![1]).toBeCloseTo(near[0], 6);
    expect(drawn[1]![2]).toBeCloseTo(near[1], 6);
  });

  it('draws a dashed line’s dashes by its line distances, and clips to the scissor box', () => {
    const { r, rec } = setup();
    r.setViewport(200, 0, 200, 150); // WebGL's origin: the bottom-right quarter
    r.setScissor(200, 0, 200, 150);
    const cam = topCamera();
    const line = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([
        new THREE.Vector3(0, 0, 0),
        new THREE.Vector3(10, 0, 0),
      ]),
      new THREE.LineDashedMaterial({ color: 0x9fd3ff, dashSize: 1, gapSize: 0.5 }),
    );
    line.computeLineDistances();
    const scene = new THREE.Scene();
    scene.add(line);
    r.render(scene, cam);
    expect(rec.ops[1]).toEqual(['rect', 200, 150, 200, 150]);
    // Dashes start every 1.5 along the 10 units: at 0, 1.5, …, 9.
    const starts = rec.ops.filter((o) => o[0] === 'moveTo');
    expect(starts).toHaveLength(7);
    const x0 = 200 + reference(new THREE.Vector3(0, 0, 0), cam, 200, 150)[0];
    const x9 = 200 + reference(new THREE.Vector3(9, 0, 0), cam, 200, 150)[0];
    expect(starts[0]![1]).toBeCloseTo(x0, 9);
    expect(starts[6]![1]).toBeCloseTo(x9, 9);
    expect(starts[0]![2]).toBeCloseTo(
      150 + reference(new THREE.Vector3(0, 0, 0), cam, 200, 150)[1],
      9,
    );
  });

  it('draws a mesh as the disc of its bounding sphere, transparent objects last', () => {
    const { r, rec } = setup();
    const cam = topCamera();
    const marker = new THREE.Mesh(
      new THREE.SphereGeometry(1, 12, 8),
      new THREE.MeshBasicMaterial({ color: 0xffe14d }),
    );
    marker.position.set(10, 0, 0);
    marker.scale.setScalar(2);
    const ghost = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints([
        new THREE.Vector3(0, 0, 0),
        new THREE.Vector3(1, 0, 0),
      ]),
      new THREE.LineBasicMaterial({ color: 0xc8d2e0, transparent: true, opacity: 0.35 }),
    );
    const scene = new THREE.Scene();
    scene.add(ghost, marker);
    r.render(scene, cam);
    const arc = rec.ops.find((o) => o[0] === 'arc')!;
    const c = reference(new THREE.Vector3(10, 0, 0), cam, 400, 300);
    expect(arc[1]).toBeCloseTo(c[0], 9);
    expect(arc[2]).toBeCloseTo(c[1], 9);
    // Radius 2 world units at 300 px / 60 units.
    expect(arc[3]).toBeCloseTo(10, 6);
    const strokes = rec.ops.filter((o) => o[0] === 'stroke' || o[0] === 'fill');
    expect(strokes).toEqual([
      ['fill', '#ffe14d'],
      ['stroke', '#c8d2e0', 0.35],
    ]);
  });
});
