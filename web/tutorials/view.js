// A small three.js view for one tutorial figure: every hex drawn shrunk toward its dual point,
// coloured by a per-hex colour function, with chords as polylines through dual points. It renders
// only when something changes (a page holds several figures).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { HEX_FACES } from './hexGeometry.js';

const SHRINK = 0.72;

export function createView(container, { onHover, onPick } = {}) {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  renderer.setClearColor(0xffffff);
  renderer.domElement.setAttribute('aria-hidden', 'true');
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(35, 1, 0.01, 1000);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.3);
  sun.position.set(3, -4, 5);
  scene.add(sun);
  const group = new THREE.Group();
  scene.add(group);
  let model = null, faceHex = null, fittedKey = null, pending = false;

  const render = () => {
    if (pending) return;
    pending = true;
    requestAnimationFrame(() => {
      pending = false;
      renderer.render(scene, camera);
    });
  };
  controls.addEventListener('change', render);

  function resize() {
    const w = container.clientWidth, h = container.clientHeight;
    if (!w || !h) return;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    render();
  }
  new ResizeObserver(resize).observe(container);

  function fit(key) {
    if (fittedKey === key) return;
    fittedKey = key;
    const box = new THREE.Box3().setFromArray(model.centroid);
    box.expandByScalar(0.5);
    const center = box.getCenter(new THREE.Vector3());
    const radius = box.getSize(new THREE.Vector3()).length() / 2 || 1;
    controls.target.copy(center);
    camera.position.copy(center).add(new THREE.Vector3(1.3, -2.4, 1.5).normalize().multiplyScalar(radius * 3.1));
    camera.near = radius / 100;
    camera.far = radius * 100;
    camera.updateProjectionMatrix();
    controls.update();
  }

  function clear() {
    for (const child of [...group.children]) {
      child.geometry.dispose();
      child.material.dispose();
      group.remove(child);
    }
  }

  // Shrunk hex corners: toward the dual point, so coincident hexes separate.
  function corner(h, c) {
    const v = model.corners[8 * h + c], p = model.dual;
    return [0, 1, 2].map((d) => p[3 * h + d] + SHRINK * (model.vertices[3 * v + d] - p[3 * h + d]));
  }

  function hexTriangles(hexes) {
    const pos = [], col = [];
    const faces = [];
    for (const { h, color } of hexes) {
      const c = new THREE.Color(color);
      for (let f = 0; f < 6; f++) {
        const q = HEX_FACES[f].map((k) => corner(h, k));
        for (const t of [0, 1, 2, 0, 2, 3]) {
          pos.push(...q[t]);
          col.push(c.r, c.g, c.b);
        }
        faces.push(h, h);
      }
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    g.setAttribute('color', new THREE.Float32BufferAttribute(col, 3));
    g.computeVertexNormals();
    return { g, faces };
  }

  function hexEdges(hexes) {
    const pos = [];
    for (const { h } of hexes) {
      for (const f of HEX_FACES) for (let k = 0; k < 4; k++) pos.push(...corner(h, f[k]), ...corner(h, f[(k + 1) % 4]));
    }
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    return g;
  }

  function addLayer(hexes, { opacity }) {
    if (!hexes.length) return [];
    const { g, faces } = hexTriangles(hexes);
    const faint = opacity < 1;
    const mesh = new THREE.Mesh(g, new THREE.MeshLambertMaterial({
      vertexColors: true, side: THREE.DoubleSide, transparent: faint, opacity, depthWrite: !faint,
    }));
    group.add(mesh);
    group.add(new THREE.LineSegments(hexEdges(hexes), new THREE.LineBasicMaterial({ color: 0x334455, transparent: true, opacity: faint ? 0.25 : 0.6 })));
    mesh.userData.faces = faces;
    return [mesh];
  }

  function addChords(chords) {
    for (const { hexes, color, closed } of chords) {
      const pts = hexes.map((h) => new THREE.Vector3(model.dual[3 * h], model.dual[3 * h + 1], model.dual[3 * h + 2]));
      if (closed && pts.length) pts.push(pts[0].clone());
      if (pts.length < 2) continue;
      const g = new THREE.BufferGeometry().setFromPoints(pts);
      // Drawn over the hexes: chords and dual points live inside them.
      const line = new THREE.Line(g, new THREE.LineBasicMaterial({ color, depthTest: false, transparent: true }));
      line.renderOrder = 2;
      group.add(line);
    }
  }

  function addDualVertices(hexes) {
    const pos = hexes.flatMap((h) => [model.dual[3 * h], model.dual[3 * h + 1], model.dual[3 * h + 2]]);
    const g = new THREE.BufferGeometry();
    g.setAttribute('position', new THREE.Float32BufferAttribute(pos, 3));
    const points = new THREE.Points(g, new THREE.PointsMaterial({ color: 0x111111, size: 7, sizeAttenuation: false, depthTest: false, transparent: true }));
    points.renderOrder = 3;
    group.add(points);
  }

  let pickables = [];
  const ray = new THREE.Raycaster();
  function hexAt(ev) {
    const r = renderer.domElement.getBoundingClientRect();
    const p = new THREE.Vector2(((ev.clientX - r.left) / r.width) * 2 - 1, -((ev.clientY - r.top) / r.height) * 2 + 1);
    ray.setFromCamera(p, camera);
    const hit = ray.intersectObjects(pickables, false)[0];
    return hit ? hit.object.userData.faces[hit.faceIndex] : -1;
  }
  let hovered = -1, down = null;
  renderer.domElement.addEventListener('pointermove', (ev) => {
    if (!model || ev.buttons) return;
    const h = hexAt(ev);
    if (h !== hovered) {
      hovered = h;
      onHover?.(h);
    }
  });
  renderer.domElement.addEventListener('pointerleave', () => {
    if (hovered !== -1) onHover?.((hovered = -1));
  });
  renderer.domElement.addEventListener('pointerdown', (ev) => (down = [ev.clientX, ev.clientY]));
  renderer.domElement.addEventListener('pointerup', (ev) => {
    if (!model || !down || Math.hypot(ev.clientX - down[0], ev.clientY - down[1]) > 4) return;
    const h = hexAt(ev);
    if (h >= 0) onPick?.(h);
  });

  return {
    canvas: renderer.domElement,
    destroy() {
      clear();
      controls.dispose();
      renderer.dispose();
      renderer.forceContextLoss();
    },
    /**
     * Draws `model` (from hexModel): `colorOf(h)` gives a colour for emphasised hexes or null for the
     * faint rest; `chords` are { hexes (dense), color, closed }; `fitKey` refits the camera when it changes.
     */
    draw(next, { colorOf, chords = [], dualVertices = false, fitKey }) {
      model = next;
      clear();
      const strong = [], faint = [];
      for (let h = 0; h < model.hexCount; h++) {
        const color = colorOf(h);
        (color ? strong : faint).push({ h, color: color || '#b8c4d6' });
      }
      const anyStrong = strong.length > 0 && faint.length > 0;
      pickables = [...addLayer(strong, { opacity: 1 }), ...addLayer(faint, { opacity: anyStrong ? 0.22 : 1 })];
      addChords(chords);
      if (dualVertices) addDualVertices([...Array(model.hexCount).keys()]);
      fit(fitKey);
      resize();
      render();
    },
  };
}
