// The 3D view: hexes shrunk toward their centres; the selected sheet or chord opaque and coloured,
// everything else faint. Buffers come from the wasm module (built in C++).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { sheetColor, chordColor } from './colors.js';

export function createView3d(container) {
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  renderer.setClearColor(0xffffff);
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1000);
  const controls = new OrbitControls(camera, renderer.domElement);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 2.2));
  const sun = new THREE.DirectionalLight(0xffffff, 1.4);
  sun.position.set(3, 5, 4);
  scene.add(sun);

  const group = new THREE.Group();
  scene.add(group);
  let buffers = null;
  let fitted = null;

  function resize() {
    const w = container.clientWidth, h = container.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
  }

  function fit(positions, key) {
    if (fitted === key) return;
    fitted = key;
    const box = new THREE.Box3().setFromArray(positions);
    const center = box.getCenter(new THREE.Vector3());
    const radius = box.getSize(new THREE.Vector3()).length() / 2 || 1;
    controls.target.copy(center);
    camera.position.copy(center).add(new THREE.Vector3(1.6, -2.2, 1.4).normalize().multiplyScalar(radius * 3.2));
    camera.up.set(0, 0, 1);
    camera.near = radius / 100;
    camera.far = radius * 100;
    camera.updateProjectionMatrix();
  }

  function rebuild(rb, highlight, color, meshKey, closed) {
    buffers = rb;
    for (const child of [...group.children]) {
      child.geometry.dispose();
      child.material.dispose();
      group.remove(child);
    }
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(rb.positions, 3));
    geometry.setAttribute('normal', new THREE.BufferAttribute(rb.normals, 3));
    const on = [], off = [];
    for (let t = 0; t < rb.triangleHex.length; t++) {
      const dest = highlight && highlight.has(rb.triangleHex[t]) ? on : off;
      dest.push(rb.indices[3 * t], rb.indices[3 * t + 1], rb.indices[3 * t + 2]);
    }
    // Faint when something is highlighted, and for closed complexes (an outer cell hides the rest).
    const faint = (highlight && highlight.size > 0) || closed;
    const rest = geometry.clone();
    rest.setIndex(off);
    group.add(
      new THREE.Mesh(
        rest,
        new THREE.MeshStandardMaterial({
          color: 0xb8c4d6,
          transparent: faint,
          opacity: highlight && highlight.size > 0 ? 0.18 : faint ? 0.35 : 1,
          depthWrite: !faint,
          roughness: 0.8,
          side: THREE.DoubleSide,
        }),
      ),
    );
    if (on.length) {
      geometry.setIndex(on);
      group.add(new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ color, roughness: 0.6, side: THREE.DoubleSide })));
    }
    fit(rb.positions, meshKey);
  }

  function frame() {
    controls.update();
    renderer.render(scene, camera);
    requestAnimationFrame(frame);
  }
  new ResizeObserver(resize).observe(container);
  resize();
  frame();

  return {
    /** Redraws from the app state: mesh, shrink and selection. */
    update(state) {
      if (!state.mesh) return;
      const rb = state.mesh.renderBuffers({ shrink: state.shrink });
      let highlight = null, color = '#888';
      if (state.selection) {
        const { kind, id } = state.selection;
        highlight = new Set(kind === 'sheet' ? state.mesh.sheetHexes(id) : state.mesh.chordHexes(id));
        color = kind === 'sheet' ? sheetColor(id) : chordColor(id);
      }
      rebuild(rb, highlight, color, state.meshKey, state.mesh.counts.boundaryQuads === 0);
    },
    get triangleCount() {
      return buffers ? buffers.triangleHex.length : 0;
    },
    canvas: renderer.domElement,
  };
}
