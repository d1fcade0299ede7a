// The 3D view of a tutorial figure, built from the explorer's parts (web/view3d/): every hex
// shrunk toward its dual point from the engine's render buffers, one colour per hex (null: the faint
// rest), chords as polylines through dual points, picking of hexes, quads and edges, marks, an
// optional per-hex layout (the exploded 4-cube), and each step animated. Renders only on change.
import * as THREE from 'three';
import { hexTables } from '../../wasm/index.js';
import { rgbOf } from '../paint.js';
import { createScene } from '../view3d/scene.js';
import { createHexLayers } from '../view3d/meshBuffers.js';
import { pickRay, classifyHit, pointNearEdge, faceSideEdge } from '../view3d/picking.js';
import { clearGroup, drawMarks } from '../view3d/overlays.js';
import { showGhosts, animateStep } from '../view3d/animation.js';
import { STEP_MS } from '../motion.js';

const BASE = [184, 196, 214];

// Applies a per-hex transform (hex id, x, y, z -> [x, y, z]) to render buffers, in place.
function transformBuffers(rb, transform) {
  const move = (arr, i, h) => {
    const p = transform(h, arr[i], arr[i + 1], arr[i + 2]);
    arr[i] = p[0], arr[i + 1] = p[1], arr[i + 2] = p[2];
  };
  for (let k = 0; k < rb.triangleHex.length / 12; k++) for (let v = 0; v < 24; v++) move(rb.positions, 3 * (24 * k + v), rb.triangleHex[12 * k]);
  if (rb.edgePositions) for (let s = 0; s < rb.edgeHex.length; s++) for (let e = 0; e < 2; e++) move(rb.edgePositions, 3 * (2 * s + e), rb.edgeHex[s]);
  return rb;
}

/**
 * A view in `container`. `onHover(pick)` and `onPick(pick, event)` get { kind, hex, face | edge }
 * or null, picked as `pickMode()` says ('hex', 'auto': quad or edge near a side, 'quad', 'edge').
 */
export function createView(container, { onHover, onPick, pickMode = () => 'hex' } = {}) {
  const sc = createScene(container, { antialias: true, fov: 35, headlight: true });
  sc.canvas.setAttribute('aria-hidden', 'true');
  const tables = hexTables();
  const layers = createHexLayers();
  const chords = new THREE.Group(), marks = new THREE.Group(), ghosts = new THREE.Group();
  sc.scene.add(...layers.objects, chords, ghosts, marks);
  let geomKey = null, fittedKey = null, transform = null, dualPoints = null, motion = null;

  const ray = new THREE.Raycaster();
  const pickAt = (x, y, mode = pickMode()) => classifyHit(layers, tables, pickRay(layers, sc.rayAt(ray, x, y)), mode);
  let down = null, hoverTimer = 0, hovered = '';
  sc.canvas.addEventListener('pointerdown', (e) => (down = [e.clientX, e.clientY]));
  sc.canvas.addEventListener('pointerup', (e) => {
    if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
    onPick?.(pickAt(e.clientX, e.clientY), e);
  });
  sc.canvas.addEventListener('pointermove', (e) => {
    clearTimeout(hoverTimer);
    if (e.buttons) return;
    hoverTimer = setTimeout(() => {
      const p = pickAt(e.clientX, e.clientY);
      const key = JSON.stringify(p);
      if (key !== hovered) (hovered = key), onHover?.(p);
    }, 30);
  });
  sc.canvas.addEventListener('pointerleave', () => {
    clearTimeout(hoverTimer);
    if (hovered !== 'null') (hovered = 'null'), onHover?.(null);
  });

  // Labels over the canvas at hexes' drawn centres, moved with the camera.
  const labelBox = Object.assign(document.createElement('div'), { className: 'hex-labels' });
  container.appendChild(labelBox);
  let labels = [];
  function setLabels(list) {
    labels = list.map((l) => {
      const e = Object.assign(document.createElement('span'), { textContent: l.text, className: l.cls || '', title: l.title || '' });
      e.dataset.hex = l.hex;
      labelBox.appendChild(e);
      return { ...l, el: e };
    });
  }
  // The highest drawn corner of a hex that lies inside the view (a label for an enclosing shell).
  function cornerInView(k, r) {
    let best = null;
    for (let v = 0; v < 24; v++) {
      const p = sc.toPage(layers.vertexAt(24 * k + v));
      const inside = p.x > r.left + 30 && p.x < r.right - 30 && p.y > r.top + 12 && p.y < r.bottom - 12;
      if (inside && (!best || p.y < best.y)) best = p;
    }
    return best ?? sc.toPage(layers.centreOf(k));
  }
  sc.onFrame(() => {
    if (!labels.length) return;
    const r = container.getBoundingClientRect();
    for (const l of labels) {
      const k = layers.slotOf(l.hex);
      l.el.hidden = k < 0;
      if (k < 0) continue;
      const p = l.anchor === 'corner' ? cornerInView(k, r) : sc.toPage(layers.centreOf(k));
      l.el.style.transform = `translate(${(p.x - r.left).toFixed(1)}px, ${(p.y - r.top).toFixed(1)}px) translate(-50%, -50%)`;
    }
  });

  function dualPoint(h) {
    const p = [dualPoints[3 * h], dualPoints[3 * h + 1], dualPoints[3 * h + 2]];
    return new THREE.Vector3(...(transform ? transform(h, ...p) : p));
  }

  function drawChords(list) {
    clearGroup(chords);
    for (const { hexes, color, closed } of list) {
      const pts = hexes.map(dualPoint);
      if (closed && pts.length) pts.push(pts[0].clone());
      if (pts.length < 2) continue;
      // Drawn over the hexes: chords and dual points live inside them.
      const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(pts), new THREE.LineBasicMaterial({ color, depthTest: false, transparent: true }));
      line.renderOrder = 4;
      chords.add(line);
    }
  }

  function drawDualVertices() {
    const pos = [];
    for (const h of layers.drawnHexIds()) pos.push(...dualPoint(h).toArray());
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    const points = new THREE.Points(g, new THREE.PointsMaterial({ color: 0x111111, size: 7, sizeAttenuation: false, depthTest: false, transparent: true }));
    points.renderOrder = 5;
    chords.add(points);
  }

  // colorOf(h): a CSS colour, [css, alpha 0..255], or null for the faint rest.
  function paint(colorOf, faintAlpha) {
    const strong = new Map();
    for (const h of layers.drawnHexIds()) {
      const c = colorOf(h);
      if (c) strong.set(h, Array.isArray(c) ? [...rgbOf(c[0]), c[1]] : [...rgbOf(c), 255]);
    }
    const alpha = strong.size > 0 && strong.size < layers.hexCount ? faintAlpha : 255;
    const rest = [...BASE, alpha];
    layers.paint((h) => strong.get(h) || rest);
    paintEdges((h) => ((strong.get(h) || rest)[3] >= 128 ? 190 : 45));
  }

  // Edge lines in one colour, strong for emphasised hexes and light for the faint rest.
  function paintEdges(alphaOf) {
    const rb = layers.rb;
    if (!rb.edgeHex) return;
    const col = new Uint8Array(8 * rb.edgeHex.length);
    for (let s = 0; s < rb.edgeHex.length; s++) {
      const a = alphaOf(rb.edgeHex[s]);
      col.set([51, 68, 85, a, 51, 68, 85, a], 8 * s);
    }
    const g = layers.edgeLines.geometry;
    g.setAttribute('color', new THREE.BufferAttribute(col, 4, true));
    layers.edgeLines.material.vertexColors = true;
    layers.edgeLines.material.opacity = 1;
    layers.edgeLines.material.needsUpdate = true;
  }

  // What the camera frames: every hex but an enclosing shell (the 4-cube's outer cube) when there is one.
  function fitPositions(rb) {
    if (!transform?.outer?.size) return rb.positions;
    const keep = [];
    for (let k = 0; k < rb.triangleHex.length / 12; k++) if (!transform.outer.has(rb.triangleHex[12 * k])) keep.push(k);
    const out = new Float32Array(72 * keep.length);
    keep.forEach((k, i) => out.set(rb.positions.subarray(72 * k, 72 * k + 72), 72 * i));
    return out.length ? out : rb.positions;
  }

  // New geometry for the mesh; animates from the previous drawing when asked.
  function rebuild(mesh, o) {
    motion?.cancel();
    const prevRb = layers.rb;
    transform = o.layout ? o.layout(mesh) : null;
    let rb = mesh.renderBuffers({ shrink: o.shrink ?? 0.28, edges: true });
    if (transform) rb = transformBuffers(rb, transform);
    dualPoints = mesh.dualPoints();
    layers.setBuffers(rb, true);
    if (fittedKey !== o.fitKey) {
      fittedKey = o.fitKey;
      sc.fit(fitPositions(rb), [1.3, -2.4, 1.5], 3.2);
    }
    return o.animate ? prevRb : null;
  }

  function animate(prevRb, { created = [], removed = [] }) {
    clearGroup(ghosts);
    if (!prevRb) return;
    showGhosts(ghosts, prevRb, removed, sc.requestRender, { from: 0.55, to: 0, ms: STEP_MS });
    motion = animateStep(layers, prevRb, { created, requestRender: sc.requestRender });
  }

  const view = {
    canvas: sc.canvas,
    tables,
    scene: sc,
    get animating() {
      return !!motion?.running;
    },
    /** The current layout transform (with `outer`: hexes drawn as the enclosing shell), or null. */
    get layoutInfo() {
      return transform;
    },
    /**
     * Draws `mesh`: `key` names its state (same key: colours, chords and marks only); `colorOf(hexId)`
     * gives a CSS colour for emphasised hexes or null for the faint rest (`faintAlpha`, 0..255);
     * `chords` are { hexes (ids), color, closed }; `fitKey` refits the camera when it changes;
     * `layout(mesh)` gives a per-hex transform; `animate` = { created, removed } animates from the
     * previous drawing; `marks` = [[pick, color, opacity]]; `labels` (or a function giving them) =
     * [{ hex, text, cls, title, anchor }] over the canvas.
     */
    draw(mesh, o) {
      let prevRb = null;
      sc.resize(); // the camera's aspect before a first fit
      if (geomKey !== o.key) {
        prevRb = rebuild(mesh, o);
        geomKey = o.key;
      }
      paint(o.colorOf, o.faintAlpha ?? 56);
      labelBox.replaceChildren();
      setLabels((typeof o.labels === 'function' ? o.labels() : o.labels) || []);
      drawChords(o.chords || []);
      if (o.dualVertices) drawDualVertices();
      drawMarks(marks, layers, tables, o.marks || []);
      if (prevRb) animate(prevRb, o.animate);
      sc.resize();
      sc.requestRender();
    },
    /** Marks only (hover, selection): no repaint of the hexes. */
    setMarks(items) {
      drawMarks(marks, layers, tables, items);
      sc.requestRender();
    },
    pickAt,
    /** Page position of a hex's drawn centre, a face centre, or a point of the face near an edge. */
    project(hex, face, edge) {
      const k = layers.slotOf(hex);
      if (k < 0) return null;
      if (face === undefined) return sc.toPage(layers.centreOf(k));
      if (edge === undefined) return sc.toPage(layers.faceCentre(k, face));
      const p = pointNearEdge(layers, tables, k, face, edge);
      return p && sc.toPage(p);
    },
    /**
     * Page points spread over face `face` of a hex, or along its side on local edge `edge` (just
     * inside the face): where a pick of that quad or edge can land (tests, hints).
     */
    facePoints(hex, face, edge) {
      const k = layers.slotOf(hex);
      if (k < 0) return [];
      const c = [0, 1, 2, 3].map((q) => layers.vertexAt(24 * k + 4 * face + q));
      const centre = layers.faceCentre(k, face);
      const out = [];
      if (edge === undefined) {
        for (const u of [0.5, 0.3, 0.7, 0.15, 0.85])
          for (const v of [0.5, 0.3, 0.7, 0.15, 0.85]) out.push(c[0].clone().lerp(c[1], u).lerp(c[3].clone().lerp(c[2], u), v));
      } else {
        const q = [0, 1, 2, 3].find((i) => faceSideEdge(tables, face, i) === edge);
        if (q === undefined) return [];
        for (const t of [0.5, 0.35, 0.65, 0.2, 0.8]) for (const inset of [0.04, 0.08]) out.push(c[q].clone().lerp(c[(q + 1) & 3], t).lerp(centre, inset));
      }
      return out.map((p) => sc.toPage(p));
    },
    /** The drawn centre of a hex in the scene (for labels). */
    centreOf(hex) {
      const k = layers.slotOf(hex);
      return k < 0 ? null : layers.centreOf(k);
    },
    drawnHexIds: () => layers.drawnHexIds(),
    destroy() {
      motion?.cancel();
      clearGroup(chords);
      clearGroup(marks);
      clearGroup(ghosts);
      sc.dispose();
    },
  };
  return view;
}
