// The 3D view: every hex shrunk toward its own dual point (a pillow pair draws apart), picking of
// hexes, quads and edges, a dual overlay, a slicing plane and ghosts of removed hexes.
// Geometry is rebuilt only when the mesh changes; selection and highlights rewrite the colour
// attribute. Frames are drawn only when something changed (requestRender).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { hexTables } from '../wasm/index.js';
import { sheetColor, chordColor } from './colors.js';
import { hexColors, paintKeyOf } from './paint.js';

const EDGE_LINES_MAX_HEXES = 8000;
// Above this many hexes only the shell is drawn (hexes with a face on the boundary or on the cut of
// the slicing plane) plus the hexes the last step created: 47^3 draws 13k hexes, not 104k.
export const SHELL_MIN_HEXES = 20000;
const ACCENT = new THREE.Color('#ff7a00');

function rgb(css) {
  return new THREE.Color(css);
}

/**
 * Creates a 3D view in `container`. `options.onPick(pick, event)` and `options.onHover(pick, event)`
 * receive {hex, face, edge, kind} or null; `options.onCamera()` fires after the user moves the camera.
 */
export function createView3d(container, options = {}) {
  const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  renderer.setClearColor(0xffffff);
  renderer.localClippingEnabled = true;
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  const hemi = new THREE.HemisphereLight(0xffffff, 0x8a96a8, 2.2);
  hemi.position.set(0, 0, 1); // z is up
  scene.add(hemi);
  const sun = new THREE.DirectionalLight(0xffffff, 1.4);
  sun.position.set(3, 5, 4);
  scene.add(sun);
  const clipPlane = new THREE.Plane(new THREE.Vector3(0, 0, -1), 0);
  const tables = hexTables();

  const geometry = { rb: null, key: null, hexSlot: null, centres: null, radii: null, hexCount: 0 };
  const solid = new THREE.Mesh(
    new THREE.BufferGeometry(),
    // Lambert and front faces: SwiftShader (software GL) spends its frame on fragments. A slice
    // turns on both sides so the cut hexes show their insides.
    new THREE.MeshLambertMaterial({ vertexColors: true, alphaTest: 0.5 }),
  );
  const faint = new THREE.Mesh(
    solid.geometry,
    new THREE.MeshLambertMaterial({ vertexColors: true, transparent: true, depthWrite: false }),
  );
  faint.renderOrder = 2;
  // The hexes the last step created, drawn again over everything while the rest is dimmed (x-ray):
  // a change deep inside is otherwise washed out by the faint layers in front of it. Front faces
  // only, so each (convex) hex draws as itself.
  const fresh = new THREE.Mesh(
    new THREE.BufferGeometry(),
    new THREE.MeshLambertMaterial({ vertexColors: true, transparent: true, depthWrite: false, depthTest: false }),
  );
  fresh.renderOrder = 2.5;
  fresh.visible = false;
  const edgeLines = new THREE.LineSegments(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0x44506a, transparent: true, opacity: 0.45 }));
  const marks = new THREE.Group(); // selected quad / edge and hover
  const overlay = new THREE.Group();
  const ghosts = new THREE.Group();
  scene.add(solid, faint, fresh, edgeLines, overlay, ghosts, marks);
  let fitted = null;
  let paintKey = null;
  let overlayKey = null;
  let hasFaint = false;

  let renderQueued = false;
  function requestRender() {
    if (renderQueued) return;
    renderQueued = true;
    requestAnimationFrame(() => {
      renderQueued = false;
      const t0 = performance.now();
      renderer.render(scene, camera);
      view.lastFrameMs = performance.now() - t0;
      view.frames++;
    });
  }
  controls.addEventListener('change', requestRender);
  controls.addEventListener('end', () => options.onCamera?.());

  function resize() {
    const w = container.clientWidth, h = container.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    requestRender();
  }

  function fit(positions) {
    const box = new THREE.Box3().setFromArray(positions);
    const center = box.getCenter(new THREE.Vector3());
    const radius = box.getSize(new THREE.Vector3()).length() / 2 || 1;
    controls.target.copy(center);
    camera.position.copy(center).add(new THREE.Vector3(1.6, -2.2, 1.4).normalize().multiplyScalar(radius * 3.2));
    camera.near = radius / 100;
    camera.far = radius * 100;
    camera.updateProjectionMatrix();
    controls.update();
  }

  // Per-hex bounding spheres for picking (hex k of the buffer owns vertices 24k..24k+23).
  function indexHexes(rb) {
    const n = rb.triangleHex.length / 12;
    let cap = 0;
    for (let k = 0; k < n; k++) cap = Math.max(cap, rb.triangleHex[12 * k] + 1);
    const hexSlot = new Int32Array(cap).fill(-1);
    const centres = new Float32Array(3 * n), radii = new Float32Array(n);
    const p = rb.positions;
    for (let k = 0; k < n; k++) {
      hexSlot[rb.triangleHex[12 * k]] = k;
      let x = 0, y = 0, z = 0;
      for (let i = 72 * k, end = i + 72; i < end; i += 3) (x += p[i]), (y += p[i + 1]), (z += p[i + 2]);
      x /= 24, y /= 24, z /= 24;
      let r2 = 0;
      for (let i = 72 * k, end = i + 72; i < end; i += 3) {
        const dx = p[i] - x, dy = p[i + 1] - y, dz = p[i + 2] - z;
        r2 = Math.max(r2, dx * dx + dy * dy + dz * dz);
      }
      centres[3 * k] = x, centres[3 * k + 1] = y, centres[3 * k + 2] = z;
      radii[k] = Math.sqrt(r2);
    }
    Object.assign(geometry, { hexSlot, centres, radii, hexCount: n });
  }

  // Hex ids on the far side of the slicing plane (shell mode cuts by leaving them out).
  function hiddenBySlice(mesh, slice) {
    const c = mesh.hexCenters();
    const n = c.length / 3;
    let lo = Infinity, hi = -Infinity;
    for (let h = 0; h < n; h++) {
      const v = c[3 * h + slice.axis]; // NaN for removed hexes: never hidden, never the range
      if (v < lo) lo = v;
      if (v > hi) hi = v;
    }
    const at = lo + slice.at * (hi - lo);
    const hidden = new Uint8Array(n);
    for (let h = 0; h < n; h++) hidden[h] = c[3 * h + slice.axis] > at ? 1 : 0;
    return hidden;
  }

  function rebuild(mesh, shrink, drawn) {
    const shell = mesh.counts.hexes >= SHELL_MIN_HEXES;
    const big = shell || mesh.counts.hexes > EDGE_LINES_MAX_HEXES;
    const rb = mesh.renderBuffers({
      shrink, edges: !big, shell,
      hidden: shell && drawn.slice ? hiddenBySlice(mesh, drawn.slice) : null,
      always: drawn.always,
    });
    view.shell = shell;
    view.builds++;
    geometry.rb = rb;
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(rb.positions, 3));
    g.setAttribute('normal', new THREE.BufferAttribute(rb.normals, 3));
    g.setAttribute('color', new THREE.BufferAttribute(new Uint8Array((rb.positions.length / 3) * 4), 4, true));
    g.setIndex(new THREE.BufferAttribute(rb.indices, 1));
    solid.geometry.dispose();
    solid.geometry = g;
    faint.geometry = g;
    edgeLines.geometry.dispose();
    edgeLines.geometry = new THREE.BufferGeometry();
    if (!big) edgeLines.geometry.setAttribute('position', new THREE.BufferAttribute(rb.edgePositions, 3));
    edgeLines.visible = !big;
    indexHexes(rb);
    paintKey = null;
    overlayKey = null;
  }

  // Writes one RGBA per hex into the colour attribute (24 vertices per hex).
  function paint(colorOf) {
    const attr = solid.geometry.getAttribute('color');
    // One RGBA word per vertex: fill 24 words per hex.
    const words = new Uint32Array(attr.array.buffer, attr.array.byteOffset, attr.array.length / 4);
    const th = geometry.rb.triangleHex;
    const word = new Uint32Array(1), bytes = new Uint8Array(word.buffer);
    hasFaint = false;
    for (let k = 0; k < geometry.hexCount; k++) {
      const c = colorOf(th[12 * k]);
      if (c[3] < 128) hasFaint = true;
      bytes.set(c);
      words.fill(word[0], 24 * k, 24 * k + 24);
    }
    attr.needsUpdate = true;
    faint.visible = hasFaint;
  }

  // Shares the solid's attributes; only the index lists the created hexes' triangles.
  function showFresh(created) {
    const slot = (h) => (h < geometry.hexSlot.length ? geometry.hexSlot[h] : -1);
    const ks = (created || []).map(slot).filter((k) => k >= 0);
    fresh.visible = ks.length > 0;
    if (!fresh.visible) return;
    const src = geometry.rb.indices;
    const idx = new Uint32Array(36 * ks.length);
    ks.forEach((k, i) => idx.set(src.subarray(36 * k, 36 * k + 36), 36 * i));
    const g = new THREE.BufferGeometry();
    for (const name of ['position', 'normal', 'color']) g.setAttribute(name, solid.geometry.getAttribute(name));
    g.setIndex(new THREE.BufferAttribute(idx, 1));
    fresh.geometry = g;
  }

  // ---- picking ----
  const ray = new THREE.Raycaster();
  function rayHitsTriangle(o, d, p, i0, i1, i2) {
    const ax = p[3 * i0], ay = p[3 * i0 + 1], az = p[3 * i0 + 2];
    const e1x = p[3 * i1] - ax, e1y = p[3 * i1 + 1] - ay, e1z = p[3 * i1 + 2] - az;
    const e2x = p[3 * i2] - ax, e2y = p[3 * i2 + 1] - ay, e2z = p[3 * i2 + 2] - az;
    const px = d.y * e2z - d.z * e2y, py = d.z * e2x - d.x * e2z, pz = d.x * e2y - d.y * e2x;
    const det = e1x * px + e1y * py + e1z * pz;
    if (Math.abs(det) < 1e-12) return Infinity;
    const inv = 1 / det;
    const tx = o.x - ax, ty = o.y - ay, tz = o.z - az;
    const u = (tx * px + ty * py + tz * pz) * inv;
    if (u < 0 || u > 1) return Infinity;
    const qx = ty * e1z - tz * e1y, qy = tz * e1x - tx * e1z, qz = tx * e1y - ty * e1x;
    const v = (d.x * qx + d.y * qy + d.z * qz) * inv;
    if (v < 0 || u + v > 1) return Infinity;
    const t = (e2x * qx + e2y * qy + e2z * qz) * inv;
    return t > 0 ? t : Infinity;
  }

  function visibleHex(k) {
    if (!view.slice || view.shell) return true;
    const c = geometry.centres;
    return clipPlane.distanceToPoint(new THREE.Vector3(c[3 * k], c[3 * k + 1], c[3 * k + 2])) >= 0;
  }

  /** The hex, face and point under a canvas position (CSS px), preferring opaque hexes. */
  function pickAt(clientX, clientY) {
    if (!geometry.rb) return null;
    const rect = renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    ray.setFromCamera(ndc, camera);
    const o = ray.ray.origin, d = ray.ray.direction;
    const { centres, radii, hexCount, rb } = geometry;
    const cand = [];
    for (let k = 0; k < hexCount; k++) {
      const cx = centres[3 * k] - o.x, cy = centres[3 * k + 1] - o.y, cz = centres[3 * k + 2] - o.z;
      const along = cx * d.x + cy * d.y + cz * d.z;
      const off2 = cx * cx + cy * cy + cz * cz - along * along;
      if (off2 <= radii[k] * radii[k]) cand.push([along - radii[k], k]);
    }
    cand.sort((a, b) => a[0] - b[0]);
    const colors = solid.geometry.getAttribute('color').array;
    let best = null, bestFaint = null;
    for (const [enter, k] of cand) {
      if (best && enter > best.t) break;
      if (!visibleHex(k)) continue;
      const isFaint = colors[4 * 24 * k + 3] < 128;
      for (let t = 12 * k; t < 12 * k + 12; t++) {
        const hitT = rayHitsTriangle(o, d, rb.positions, rb.indices[3 * t], rb.indices[3 * t + 1], rb.indices[3 * t + 2]);
        if (hitT === Infinity) continue;
        const hit = { t: hitT, k, tri: t };
        if (isFaint) {
          if (!bestFaint || hitT < bestFaint.t) bestFaint = hit;
        } else if (!best || hitT < best.t) best = hit;
      }
    }
    const h = best || bestFaint;
    if (!h) return null;
    const point = o.clone().addScaledVector(d, h.t);
    return { hex: rb.triangleHex[h.tri], face: rb.triangleFace[h.tri], faceIndex: h.tri >> 1, point };
  }

  function vertexAt(i) {
    const p = geometry.rb.positions;
    return new THREE.Vector3(p[3 * i], p[3 * i + 1], p[3 * i + 2]);
  }

  // The local edge of face f between its buffer corners q and q+1.
  function faceSideEdge(f, q) {
    const fc = tables.faceCorners, ec = tables.edgeCorners;
    const a = fc[4 * f + q], b = fc[4 * f + ((q + 1) & 3)];
    for (let e = 0; e < 12; e++) if ((ec[2 * e] === a && ec[2 * e + 1] === b) || (ec[2 * e] === b && ec[2 * e + 1] === a)) return e;
    return -1;
  }

  /** Classifies a hit as a quad, or an edge when it is near a side of the face (mode 'auto'). */
  function classify(hit, mode) {
    if (!hit) return null;
    if (mode === 'hex') return { kind: 'hex', hex: hit.hex };
    const corners = [0, 1, 2, 3].map((q) => vertexAt(4 * hit.faceIndex + q));
    let nearest = -1, nearestD = Infinity, size = 0;
    for (let q = 0; q < 4; q++) {
      const seg = new THREE.Line3(corners[q], corners[(q + 1) & 3]);
      const d = seg.closestPointToPoint(hit.point, true, new THREE.Vector3()).distanceTo(hit.point);
      size += seg.distance() / 4;
      if (d < nearestD) (nearestD = d), (nearest = q);
    }
    if (mode === 'edge' || (mode === 'auto' && nearestD < 0.14 * size)) {
      return { kind: 'edge', hex: hit.hex, edge: faceSideEdge(hit.face, nearest) };
    }
    return { kind: 'quad', hex: hit.hex, face: hit.face };
  }

  // ---- marks: the selected quad or edge, drawn over the hexes ----
  function cornerPosition(k, corner) {
    const fc = tables.faceCorners;
    for (let f = 0; f < 6; f++) for (let q = 0; q < 4; q++) if (fc[4 * f + q] === corner) return vertexAt(24 * k + 4 * f + q);
    return null;
  }

  function clearGroup(group) {
    for (const child of [...group.children]) {
      child.geometry?.dispose();
      child.material?.dispose();
      group.remove(child);
    }
  }

  function markQuad(k, face, color, opacity) {
    const base = 24 * k + 4 * face;
    const centre = new THREE.Vector3();
    const pts = [0, 1, 2, 3].map((q) => vertexAt(base + q));
    pts.forEach((p) => centre.add(p));
    centre.multiplyScalar(0.25);
    // Slightly inside the face outline and lifted off it so it never z-fights.
    const n = new THREE.Vector3(...geometry.rb.normals.slice(3 * base, 3 * base + 3));
    const size = pts[0].distanceTo(pts[2]);
    // A frame, not a filled quad: what a step puts at the quad (a pillow's hexes) stays visible.
    const outer = pts.map((p) => p.clone().lerp(centre, 0.06).addScaledVector(n, 0.01 * size));
    const inner = pts.map((p) => p.clone().lerp(centre, 0.3).addScaledVector(n, 0.01 * size));
    const tri = [];
    for (let q = 0; q < 4; q++) {
      const r = (q + 1) & 3;
      tri.push(outer[q], outer[r], inner[r], outer[q], inner[r], inner[q]);
    }
    const g = new THREE.BufferGeometry().setFromPoints(tri);
    const m = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color, side: THREE.DoubleSide, transparent: opacity < 1, opacity, depthTest: false }));
    m.renderOrder = 5;
    marks.add(m);
  }

  function markEdge(k, edge, color) {
    const ec = tables.edgeCorners;
    const a = cornerPosition(k, ec[2 * edge]), b = cornerPosition(k, ec[2 * edge + 1]);
    const len = a.distanceTo(b);
    const g = new THREE.CylinderGeometry(0.035 * len, 0.035 * len, len, 8);
    const m = new THREE.Mesh(g, new THREE.MeshBasicMaterial({ color, depthTest: false }));
    m.renderOrder = 6;
    m.position.copy(a).add(b).multiplyScalar(0.5);
    m.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), b.clone().sub(a).normalize());
    marks.add(m);
  }

  function drawMarks(selection, hover) {
    clearGroup(marks);
    const slot = (h) => (geometry.hexSlot && h < geometry.hexSlot.length ? geometry.hexSlot[h] : -1);
    for (const [s, color, opacity] of [[hover, '#1f6feb', 0.45], [selection, ACCENT, 0.9]]) {
      if (!s) continue;
      const k = slot(s.hex);
      if (k < 0) continue;
      if (s.kind === 'quad') markQuad(k, s.face, color, opacity);
      if (s.kind === 'edge') markEdge(k, s.edge, color);
    }
    requestRender();
  }

  function drawnHexIds() {
    const th = geometry.rb.triangleHex;
    const ids = new Int32Array(geometry.hexCount);
    for (let k = 0; k < ids.length; k++) ids[k] = th[12 * k];
    return ids;
  }

  // ---- dual overlay (TK03 Fig. 1) ----
  function buildOverlay(mesh) {
    clearGroup(overlay);
    // A shell's overlay covers the drawn hexes only (all of 47^3 is 311k sheet quads).
    const o = view.shell ? mesh.dualOverlay({ hexes: drawnHexIds() }) : mesh.dualOverlay();
    const nTri = o.sheetTriangle.length;
    const sheetColors = new Float32Array(o.sheetPositions.length);
    const cache = new Map();
    for (let t = 0; t < nTri; t += 2) {
      const id = o.sheetTriangle[t];
      if (!cache.has(id)) cache.set(id, rgb(sheetColor(id)));
      const c = cache.get(id);
      const quad = t >> 1;
      for (let q = 0; q < 4; q++) sheetColors.set([c.r, c.g, c.b], 3 * (4 * quad + q));
    }
    const sg = new THREE.BufferGeometry();
    sg.setAttribute('position', new THREE.BufferAttribute(o.sheetPositions, 3));
    sg.setAttribute('color', new THREE.BufferAttribute(sheetColors, 3));
    sg.setIndex(new THREE.BufferAttribute(o.sheetIndices, 1));
    const sheets = new THREE.Mesh(sg, new THREE.MeshBasicMaterial({ vertexColors: true, transparent: true, opacity: 0.28, depthWrite: false, side: THREE.DoubleSide }));
    sheets.renderOrder = 3;
    const chordColors = new Float32Array(o.chordPositions.length);
    for (let s = 0; s < o.chordSegment.length; s++) {
      const c = rgb(chordColor(o.chordSegment[s]));
      chordColors.set([c.r, c.g, c.b, c.r, c.g, c.b], 6 * s);
    }
    const cg = new THREE.BufferGeometry();
    cg.setAttribute('position', new THREE.BufferAttribute(o.chordPositions, 3));
    cg.setAttribute('color', new THREE.BufferAttribute(chordColors, 3));
    const chords = new THREE.LineSegments(cg, new THREE.LineBasicMaterial({ vertexColors: true }));
    chords.renderOrder = 4;
    const dg = new THREE.BufferGeometry();
    dg.setAttribute('position', new THREE.BufferAttribute(o.dualVertices, 3));
    const dots = new THREE.Points(dg, new THREE.PointsMaterial({ color: 0x111111, size: 5, sizeAttenuation: false }));
    dots.renderOrder = 4;
    overlay.add(sheets, chords, dots);
    for (const obj of overlay.children) obj.material.clippingPlanes = view.slice ? [clipPlane] : [];
  }

  // ---- ghosts: removed hexes, taken from the previous buffers, fading to faint ----
  function showGhosts(prevRb, removed) {
    clearGroup(ghosts);
    if (!prevRb || !removed || removed.length === 0) return;
    const want = new Set(removed);
    const pos = [];
    const th = prevRb.triangleHex;
    for (let k = 0; k < th.length / 12; k++) {
      if (!want.has(th[12 * k])) continue;
      for (let t = 12 * k; t < 12 * k + 12; t++)
        for (let j = 0; j < 3; j++) {
          const i = prevRb.indices[3 * t + j];
          pos.push(prevRb.positions[3 * i], prevRb.positions[3 * i + 1], prevRb.positions[3 * i + 2]);
        }
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(pos), 3));
    const mat = new THREE.MeshBasicMaterial({ color: 0xd0342c, transparent: true, opacity: 0.6, depthWrite: false, side: THREE.DoubleSide });
    const m = new THREE.Mesh(g, mat);
    m.renderOrder = 3;
    ghosts.add(m);
    const start = performance.now();
    const fade = () => {
      const f = Math.min(1, (performance.now() - start) / 1200);
      mat.opacity = 0.6 - 0.45 * f;
      requestRender();
      if (f < 1 && ghosts.children.includes(m)) requestAnimationFrame(fade);
    };
    requestAnimationFrame(fade);
  }

  // ---- pointer ----
  let hoverTimer = 0, down = null;
  const el = renderer.domElement;
  el.addEventListener('pointerdown', (e) => (down = [e.clientX, e.clientY]));
  el.addEventListener('pointerup', (e) => {
    if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
    const mode = e.altKey || e.shiftKey ? 'hex' : view.pickMode;
    options.onPick?.(classify(pickAt(e.clientX, e.clientY), mode), e);
  });
  el.addEventListener('dblclick', (e) => options.onPick?.(classify(pickAt(e.clientX, e.clientY), 'hex'), e));
  el.addEventListener('pointermove', (e) => {
    clearTimeout(hoverTimer);
    if (e.buttons) return;
    hoverTimer = setTimeout(() => options.onHover?.(classify(pickAt(e.clientX, e.clientY), view.pickMode), e), 40);
  });
  el.addEventListener('pointerleave', () => {
    clearTimeout(hoverTimer);
    options.onHover?.(null, null);
  });

  new ResizeObserver(resize).observe(container);
  resize();

  let prevRb = null;
  let lastSelection = null, lastHover = null;
  const view = {
    pickMode: 'auto',
    slice: null,
    frames: 0,
    builds: 0,
    shell: false,
    lastFrameMs: 0,
    lastBuildMs: 0,
    canvas: el,
    requestRender,
    /** Draws the app state: geometry when the mesh changed, colours when the selection changed. */
    update(state) {
      const mesh = state.mesh;
      if (!mesh) return;
      // A shell also depends on the slice (what it exposes) and on the hexes the last step created.
      const shell = mesh.counts.hexes >= SHELL_MIN_HEXES;
      const report = state.report && state.report.key === state.meshKey ? state.report : null;
      const drawn = { slice: shell ? state.slice : null, always: shell && report ? report.created : null };
      const geomKey = `${state.meshKey}|${state.shrink}${shell && state.slice ? `|${state.slice.axis}:${state.slice.at}` : ''}`;
      // Frames are drawn only when something here changed (other panels' changes draw nothing).
      let dirty = false;
      if (geometry.key !== geomKey) {
        dirty = true;
        const t0 = performance.now();
        const sameMesh = geometry.key && geometry.key.split('|')[0] === state.meshKey;
        const sameStart = geometry.key && geometry.key.split('|')[0].split(':')[0] === state.meshKey.split(':')[0];
        if (!sameMesh) prevRb = sameStart ? geometry.rb : null;
        rebuild(mesh, state.shrink, drawn);
        geometry.key = geomKey;
        if (fitted !== state.meshKey.split(':')[0]) {
          fitted = state.meshKey.split(':')[0];
          if (state.camera) view.setCamera(state.camera);
          else fit(geometry.rb.positions);
        }
        if (!sameMesh) showGhosts(state.ghosts && report ? prevRb : null, report?.removed);
        if (!state.ghosts) clearGroup(ghosts);
        view.lastBuildMs = performance.now() - t0;
      }
      const pk = paintKeyOf(state);
      if (paintKey !== pk) {
        paintKey = pk;
        dirty = true;
        paint(hexColors(state));
        showFresh(report && hasFaint ? report.created : null);
        lastSelection = null;
      }
      if (lastSelection !== state.selection) {
        lastSelection = state.selection;
        drawMarks(state.selection, lastHover);
        dirty = true;
      }
      if (!state.ghosts && ghosts.children.length) {
        clearGroup(ghosts);
        dirty = true;
      }
      const ok = state.overlay ? `${geomKey}` : null;
      if (overlayKey !== ok) {
        overlayKey = ok;
        dirty = true;
        if (ok) buildOverlay(mesh);
        else clearGroup(overlay);
      }
      const sliceKey = state.slice ? `${view.shell}:${state.slice.axis}:${state.slice.at}` : '';
      if (view.sliceKey !== sliceKey) {
        view.sliceKey = sliceKey;
        view.setSlice(state.slice);
      }
      if (dirty) requestRender();
    },
    setHover(hover) {
      lastHover = hover;
      drawMarks(lastSelection, hover);
    },
    /** Cuts away everything on the far side of an axis-aligned plane (axis 0..2, `at` in [0,1] of the box). */
    setSlice(slice) {
      view.slice = slice;
      const planes = slice ? [clipPlane] : [];
      if (slice && geometry.rb) {
        const box = new THREE.Box3().setFromArray(geometry.rb.positions);
        const n = new THREE.Vector3();
        n.setComponent(slice.axis, -1);
        const at = box.min.getComponent(slice.axis) + slice.at * (box.max.getComponent(slice.axis) - box.min.getComponent(slice.axis));
        clipPlane.set(n, at);
      }
      solid.material.side = slice && !view.shell ? THREE.DoubleSide : THREE.FrontSide;
      for (const obj of [solid, faint, fresh, edgeLines, ...overlay.children]) {
        obj.material.clippingPlanes = view.shell ? [] : planes;
        obj.material.needsUpdate = true;
      }
      requestRender();
    },
    getCamera() {
      const r = (x) => Number(x.toFixed(3));
      return [...camera.position.toArray(), ...controls.target.toArray()].map(r);
    },
    setCamera(c) {
      camera.position.set(c[0], c[1], c[2]);
      controls.target.set(c[3], c[4], c[5]);
      const radius = camera.position.distanceTo(controls.target) || 1;
      camera.near = radius / 300;
      camera.far = radius * 30;
      camera.updateProjectionMatrix();
      controls.update();
      requestRender();
    },
    /** Page position (CSS px) of a hex's drawn centre, or of the centre of one of its faces. */
    project(hex, face) {
      const k = geometry.hexSlot?.[hex] ?? -1;
      if (k < 0) return null;
      let p;
      if (face === undefined) p = new THREE.Vector3(...geometry.centres.slice(3 * k, 3 * k + 3));
      else {
        p = new THREE.Vector3();
        for (let q = 0; q < 4; q++) p.add(vertexAt(24 * k + 4 * face + q));
        p.multiplyScalar(0.25);
      }
      p.project(camera);
      const rect = el.getBoundingClientRect();
      return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
    },
    pickAt: (x, y, mode = view.pickMode) => classify(pickAt(x, y), mode),
    get triangleCount() {
      return geometry.rb ? geometry.rb.triangleHex.length : 0;
    },
    /** Hexes drawn over the faint pass (the last step's created hexes while the rest is dimmed). */
    get freshCount() {
      return fresh.visible ? fresh.geometry.index.count / 36 : 0;
    },
    get ghostCount() {
      return ghosts.children.length;
    },
    get overlayShown() {
      return overlay.children.length > 0;
    },
    dispose() {
      renderer.dispose();
    },
  };
  return view;
}
