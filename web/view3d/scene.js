// The three.js scene of a 3D view: renderer, camera with orbit controls (z up), lights, frames drawn
// only on request, resizing with the container, fitting the camera to a box, and saving it.
// Shared by the explorer (view3d.js) and the tutorial figures (tutorials/view.js).
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

/**
 * A renderer in `container`. `options.onCamera()` fires after the user moved the camera;
 * `options.antialias` (default false: SwiftShader spends its frame on fragments); `options.headlight`
 * adds a light that moves with the camera.
 */
export function createScene(container, { antialias = false, fov = 40, onCamera, headlight = false } = {}) {
  const renderer = new THREE.WebGLRenderer({ antialias, preserveDrawingBuffer: true });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
  renderer.setClearColor(0xffffff);
  renderer.localClippingEnabled = true;
  container.appendChild(renderer.domElement);
  const scene = new THREE.Scene();
  const camera = new THREE.PerspectiveCamera(fov, 1, 0.01, 1000);
  camera.up.set(0, 0, 1);
  const controls = new OrbitControls(camera, renderer.domElement);
  const hemi = new THREE.HemisphereLight(0xffffff, 0x8a96a8, 2.2);
  hemi.position.set(0, 0, 1); // z is up
  scene.add(hemi);
  const sun = new THREE.DirectionalLight(0xffffff, 1.4);
  sun.position.set(3, 5, 4);
  scene.add(sun);
  // A light at the camera: faces turned toward the viewer are lit from any side (tutorial figures).
  if (headlight) {
    const head = new THREE.DirectionalLight(0xffffff, 0.9);
    head.position.set(0, 0, 1);
    camera.add(head);
    scene.add(camera);
  }
  const stats = { frames: 0, lastFrameMs: 0 };
  const beforeFrame = new Set();

  let queued = false;
  function requestRender() {
    if (queued) return;
    queued = true;
    requestAnimationFrame((now) => {
      queued = false;
      for (const fn of beforeFrame) fn(now);
      const t0 = performance.now();
      renderer.render(scene, camera);
      stats.lastFrameMs = performance.now() - t0;
      stats.frames++;
    });
  }
  controls.addEventListener('change', requestRender);
  controls.addEventListener('end', () => onCamera?.());

  function resize() {
    const w = container.clientWidth, h = container.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(h, 1);
    camera.updateProjectionMatrix();
    requestRender();
  }
  const observer = new ResizeObserver(resize);
  observer.observe(container);

  /** Looks at the box of `positions` (x, y, z triples) from `direction`, `distance` radii away. */
  function fit(positions, direction = [1.6, -2.2, 1.4], distance = 3.2) {
    const box = new THREE.Box3().setFromArray(positions);
    const center = box.getCenter(new THREE.Vector3());
    const radius = box.getSize(new THREE.Vector3()).length() / 2 || 1;
    // A view taller than wide (a phone) sees less across than up: back off so the box fits across.
    const half = (camera.fov * Math.PI) / 360, across = Math.atan(Math.tan(half) * camera.aspect);
    const portrait = camera.aspect < 1 ? Math.sin(half) / Math.sin(across) : 1;
    controls.target.copy(center);
    camera.position.copy(center).add(new THREE.Vector3(...direction).normalize().multiplyScalar(radius * distance * portrait));
    camera.near = radius / 100;
    camera.far = radius * 100;
    camera.updateProjectionMatrix();
    controls.update();
  }

  function getCamera() {
    const r = (x) => Number(x.toFixed(3));
    return [...camera.position.toArray(), ...controls.target.toArray()].map(r);
  }

  function setCamera(c) {
    camera.position.set(c[0], c[1], c[2]);
    controls.target.set(c[3], c[4], c[5]);
    const radius = camera.position.distanceTo(controls.target) || 1;
    camera.near = radius / 300;
    camera.far = radius * 30;
    camera.updateProjectionMatrix();
    controls.update();
    requestRender();
  }

  /** Page position (CSS px) of a point in the scene. */
  function toPage(point) {
    const p = point.clone().project(camera);
    const rect = renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((p.x + 1) / 2) * rect.width, y: rect.top + ((1 - p.y) / 2) * rect.height };
  }

  /** Sets `raycaster` to the ray through a page position (CSS px). */
  function rayAt(raycaster, clientX, clientY) {
    const rect = renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, camera);
    return raycaster.ray;
  }

  return {
    renderer, scene, camera, controls, stats, canvas: renderer.domElement,
    requestRender, resize, fit, getCamera, setCamera, toPage, rayAt,
    /** Runs `fn(now)` before every frame (animations); returns a function that removes it. */
    onFrame(fn) {
      beforeFrame.add(fn);
      return () => beforeFrame.delete(fn);
    },
    dispose() {
      observer.disconnect();
      controls.dispose();
      renderer.dispose();
      renderer.forceContextLoss();
    },
  };
}
