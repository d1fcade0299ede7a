// The explorer's 3D view: every hex shrunk toward its own dual point (a pillow pair draws apart),
// picking of hexes, quads and edges, a dual overlay, a slicing plane and ghosts of removed hexes.
// Geometry is rebuilt only when the mesh changes; selection and highlights rewrite the colour
// attribute. Frames are drawn only when something changed. The parts are modules in view3d/
// (scene and camera, mesh buffers, picking, overlays, animation) that the tutorials share.
import * as THREE from 'three';
import { hexTables } from '../wasm/index.js';
import { hexColors, paintKeyOf } from './paint.js';
import { createScene } from './view3d/scene.js';
import { createHexLayers, hiddenBySlice, SHELL_MIN_HEXES, EDGE_LINES_MAX_HEXES } from './view3d/meshBuffers.js';
import { pickRay, classifyHit } from './view3d/picking.js';
import { clearGroup, drawMarks, drawDualOverlay, drawSingularEdges, ACCENT, HOVER } from './view3d/overlays.js';
import { showGhosts, animateStep } from './view3d/animation.js';

export { SHELL_MIN_HEXES };

// The state's mesh key without the step part ("7:3:..." -> "7"): the same start mesh.
const startOf = (key) => key.split(':')[0];

/**
 * Creates a 3D view in `container`. `options.onPick(pick, event)` and `options.onHover(pick, event)`
 * receive {hex, face, edge, kind} or null; `options.onCamera()` fires after the user moves the camera.
 */
export function createView3d(container, options = {}) {
  const sc = createScene(container, { onCamera: options.onCamera });
  const { camera } = sc;
  const clipPlane = new THREE.Plane(new THREE.Vector3(0, 0, -1), 0);
  const tables = hexTables();
  const layers = createHexLayers();
  const marks = new THREE.Group(); // selected quad / edge and hover
  const overlay = new THREE.Group();
  const ghosts = new THREE.Group();
  const singular = new THREE.Group(); // the singularity graph's edges
  sc.scene.add(...layers.objects, overlay, ghosts, singular, marks);
  let geomKey = null, fitted = null, paintKey = null, overlayKey = null, singularKey = null;

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
    layers.setBuffers(rb, !big);
    paintKey = null;
    overlayKey = null;
  }

  function visibleSlot(k) {
    if (!view.slice || view.shell) return true;
    return clipPlane.distanceToPoint(layers.centreOf(k)) >= 0;
  }
  const ray = new THREE.Raycaster();
  function hitAt(clientX, clientY) {
    return pickRay(layers, sc.rayAt(ray, clientX, clientY), visibleSlot);
  }
  const classify = (hit, mode) => classifyHit(layers, tables, hit, mode);

  const STALE = Symbol('stale marks');
  let lastSelection = null, lastHover = null;
  function redrawMarks() {
    const selection = lastSelection === STALE ? null : lastSelection;
    // A hovered hex (a crossing under the pointer in a sheet diagram) is marked on all six faces.
    drawMarks(marks, layers, tables, [[lastHover, HOVER, 0.45, true], [selection, ACCENT, 0.9]]);
    sc.requestRender();
  }

  function buildOverlay(mesh) {
    // A shell's overlay covers the drawn hexes only (all of 47^3 is 311k sheet quads).
    const o = view.shell ? mesh.dualOverlay({ hexes: layers.drawnHexIds() }) : mesh.dualOverlay();
    drawDualOverlay(overlay, o, view.slice ? [clipPlane] : []);
  }

  // ---- pointer ----
  let hoverTimer = 0, down = null;
  const el = sc.canvas;
  el.addEventListener('pointerdown', (e) => (down = [e.clientX, e.clientY]));
  el.addEventListener('pointerup', (e) => {
    if (!down || Math.hypot(e.clientX - down[0], e.clientY - down[1]) > 4) return;
    const mode = e.altKey || e.shiftKey ? 'hex' : view.pickMode;
    options.onPick?.(classify(hitAt(e.clientX, e.clientY), mode), e);
  });
  el.addEventListener('dblclick', (e) => options.onPick?.(classify(hitAt(e.clientX, e.clientY), 'hex'), e));
  el.addEventListener('pointermove', (e) => {
    clearTimeout(hoverTimer);
    if (e.buttons) return;
    hoverTimer = setTimeout(() => options.onHover?.(classify(hitAt(e.clientX, e.clientY), view.pickMode), e), 40);
  });
  el.addEventListener('pointerleave', () => {
    clearTimeout(hoverTimer);
    options.onHover?.(null, null);
  });
  sc.resize();

  // Geometry for the state's mesh; returns whether it was rebuilt.
  function updateGeometry(state, report) {
    const mesh = state.mesh;
    // A shell also depends on the slice (what it exposes) and on the hexes the last step created.
    const shell = mesh.counts.hexes >= SHELL_MIN_HEXES;
    const drawn = { slice: shell ? state.slice : null, always: shell && report ? report.created : null };
    const key = `${state.meshKey}|${state.shrink}${shell && state.slice ? `|${state.slice.axis}:${state.slice.at}` : ''}`;
    if (geomKey === key) return false;
    motion?.cancel();
    const t0 = performance.now();
    const sameMesh = geomKey && geomKey.split('|')[0] === state.meshKey;
    const sameStart = geomKey && startOf(geomKey.split('|')[0]) === startOf(state.meshKey);
    const prevRb = !sameMesh && sameStart ? layers.rb : null;
    rebuild(mesh, state.shrink, drawn);
    geomKey = key;
    if (fitted !== startOf(state.meshKey)) {
      fitted = startOf(state.meshKey);
      if (state.camera) view.setCamera(state.camera);
      else sc.fit(layers.rb.positions);
    }
    if (!sameMesh) showGhosts(ghosts, state.ghosts && report ? prevRb : null, report?.removed, sc.requestRender);
    if (!state.ghosts) clearGroup(ghosts);
    // A step (or a move in time) on a mesh drawn whole: animated once the colours are painted.
    pendingMotion = !sameMesh && prevRb && !shell ? { prevRb, created: report?.created ?? [] } : null;
    view.lastBuildMs = performance.now() - t0;
    return true;
  }

  let pendingMotion = null, motion = null;
  function startMotion() {
    motion?.cancel();
    const m = pendingMotion;
    pendingMotion = null;
    motion = m && animateStep(layers, m.prevRb, { created: m.created, requestRender: sc.requestRender });
  }

  const view = {
    pickMode: 'auto',
    slice: null,
    builds: 0,
    singularEdges: 0, // singular edges drawn
    shell: false,
    lastBuildMs: 0,
    canvas: el,
    requestRender: sc.requestRender,
    get frames() {
      return sc.stats.frames;
    },
    get lastFrameMs() {
      return sc.stats.lastFrameMs;
    },
    /** Draws the app state: geometry when the mesh changed, colours when the selection changed. */
    update(state) {
      if (!state.mesh) return;
      const report = state.report && state.report.key === state.meshKey && !state.report.textOnly ? state.report : null;
      // Frames are drawn only when something here changed (other panels' changes draw nothing).
      let dirty = updateGeometry(state, report);
      const pk = paintKeyOf(state);
      if (paintKey !== pk) {
        paintKey = pk;
        dirty = true;
        layers.paint(hexColors(state));
        layers.showFresh(report && layers.hasFaint ? report.created : null);
        // New colours need the marks redrawn, also when the selection went from something to null.
        lastSelection = STALE;
      }
      if (lastSelection !== state.selection) {
        lastSelection = state.selection;
        redrawMarks();
        dirty = true;
      }
      if (!state.ghosts && ghosts.children.length) {
        clearGroup(ghosts);
        dirty = true;
      }
      const ok = state.overlay ? geomKey : null;
      if (overlayKey !== ok) {
        overlayKey = ok;
        dirty = true;
        if (ok) buildOverlay(state.mesh);
        else clearGroup(overlay);
      }
      const sk = state.singular ? state.meshKey : null;
      if (singularKey !== sk) {
        singularKey = sk;
        dirty = true;
        if (sk) {
          const sing = state.mesh.singularities();
          const ends = sing.edges.flatMap((e) => e.vertices);
          drawSingularEdges(singular, sing, state.mesh.vertexPositions(ends), view.slice && !view.shell ? [clipPlane] : []);
          view.singularEdges = sing.edges.length;
        } else {
          clearGroup(singular);
          view.singularEdges = 0;
        }
      }
      const sliceKey = state.slice ? `${view.shell}:${state.slice.axis}:${state.slice.at}` : '';
      if (view.sliceKey !== sliceKey) {
        view.sliceKey = sliceKey;
        view.setSlice(state.slice);
      }
      if (pendingMotion) startMotion();
      if (dirty) sc.requestRender();
    },
    /** Whether a step animation is running (tests wait for the end). */
    get animating() {
      return !!motion?.running;
    },
    setHover(hover) {
      lastHover = hover;
      redrawMarks();
    },
    /** Cuts away everything on the far side of an axis-aligned plane (axis 0..2, `at` in [0,1] of the box). */
    setSlice(slice) {
      view.slice = slice;
      const planes = slice ? [clipPlane] : [];
      if (slice && layers.rb) {
        const box = new THREE.Box3().setFromArray(layers.rb.positions);
        const n = new THREE.Vector3();
        n.setComponent(slice.axis, -1);
        const at = box.min.getComponent(slice.axis) + slice.at * (box.max.getComponent(slice.axis) - box.min.getComponent(slice.axis));
        clipPlane.set(n, at);
      }
      layers.solid.material.side = slice && !view.shell ? THREE.DoubleSide : THREE.FrontSide;
      for (const obj of [...layers.objects, ...overlay.children, ...singular.children]) {
        obj.material.clippingPlanes = view.shell ? [] : planes;
        obj.material.needsUpdate = true;
      }
      sc.requestRender();
    },
    getCamera: sc.getCamera,
    setCamera: sc.setCamera,
    /** Page position (CSS px) of a hex's drawn centre, or of the centre of one of its faces. */
    project(hex, face) {
      const k = layers.slotOf(hex);
      if (k < 0) return null;
      return sc.toPage(face === undefined ? layers.centreOf(k) : layers.faceCentre(k, face));
    },
    pickAt: (x, y, mode = view.pickMode) => classify(hitAt(x, y), mode),
    get triangleCount() {
      return layers.rb ? layers.rb.triangleHex.length : 0;
    },
    /** Hexes drawn over the faint pass (the last step's created hexes while the rest is dimmed). */
    get freshCount() {
      return layers.fresh.visible ? layers.fresh.geometry.index.count / 36 : 0;
    },
    /** Selection and hover marks drawn (0 when nothing is selected or hovered). */
    get marksShown() {
      return marks.children.length;
    },
    get ghostCount() {
      return ghosts.children.length;
    },
    get overlayShown() {
      return overlay.children.length > 0;
    },
    dispose() {
      sc.renderer.dispose();
    },
  };
  return view;
}
