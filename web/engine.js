// The mesh and its timeline over the package API: start from a spec (or file bytes), apply steps,
// move to any step K. Moving back uses the engine's exact undo when the package has it, and
// otherwise replays the first K steps from the start mesh (the same ids: replay is deterministic).
// Each change stores a report: created and removed hexes, changed sheets and chords.
import { Mesh } from '../wasm/index.js';

// Bytes of wasm heap per hex: 170-190 stay allocated after the complex and its dual (grids of
// 0.1 to 6.3 M hexes, heapBytes()), with headroom for peaks while building; a big mesh draws only
// its shell, so render buffers add little. 2 GiB is the most a wasm32 heap can grow to.
const BYTES_PER_HEX = 300;
const HEAP_LIMIT = 2 ** 31;

export function createEngine(store) {
  let serial = 0;
  let fileBytes = null;
  let hd = null, hdKey = null;

  function build(spec) {
    if (spec.kind === 'file') return Mesh.load(fileBytes, spec.name);
    if (spec.kind === 'fourcube') return Mesh.fourCube();
    const [a, b, c] = spec.dims;
    const hexes = spec.kind === 'ring' ? a * b * c : a * b * c;
    if (hexes * BYTES_PER_HEX > HEAP_LIMIT) {
      throw new Error(`${a}x${b}x${c} is ${hexes.toLocaleString('en')} hexes: about ${((hexes * BYTES_PER_HEX) / 2 ** 30).toFixed(1)} GiB of wasm memory; the limit is 2 GiB (about ${Math.floor(HEAP_LIMIT / BYTES_PER_HEX).toLocaleString('en')} hexes)`);
    }
    return spec.kind === 'ring' ? Mesh.ring(a, b, c) : Mesh.grid(a, b, c);
  }

  function key(mesh, at) {
    return `${serial}:${at}:${mesh.counts.hexes}:${++engine.revision}`;
  }

  function setMesh(mesh, patch) {
    const old = store.get().mesh;
    if (old && old !== mesh) old.delete();
    hd = null;
    const s = store.get();
    const next = { ...patch, mesh };
    next.meshKey = key(mesh, patch.at ?? s.at);
    if (s.colorBy === 'quality') next.quality = mesh.quality();
    store.set(next);
  }

  function hexDualOf(mesh) {
    return mesh.hexDual();
  }

  // Created / removed hexes from the hex liveness before and after (ids are never reused).
  function diffReport(before, after, result, step, meshKey) {
    const alive = (d, h) => 3 * h < d.sheetOf.length && d.sheetOf[3 * h] >= 0;
    let created = [], removed = [];
    if (result && typeof result === 'object' && result.created) {
      // The engine's step report: created/removed { hexes, vertices }.
      created = [...(result.created.hexes ?? result.created)];
      removed = [...(result.removed.hexes ?? result.removed)];
    } else {
      const n = Math.max(before.sheetOf.length, after.sheetOf.length) / 3;
      for (let h = 0; h < n; h++) {
        const a = alive(before, h), b = alive(after, h);
        if (b && !a) created.push(h);
        if (a && !b) removed.push(h);
      }
    }
    let changedSheets, changedChords;
    if (result && typeof result === 'object' && result.changedSheets) {
      // IdChanges { created, removed, changed }: the ids that exist afterwards and changed.
      const ids = (c) => (Array.isArray(c) ? [...c] : [...c.created, ...c.changed].sort((x, y) => x - y));
      changedSheets = ids(result.changedSheets);
      changedChords = ids(result.changedChords);
    } else {
      const sheets = new Set(), chords = new Set();
      for (const [d, hs] of [[after, created], [before, removed]])
        for (const h of hs)
          for (let a = 0; a < 3; a++) {
            if (d.sheetOf[3 * h + a] >= 0) sheets.add(d.sheetOf[3 * h + a]);
            if (d.chordOf[3 * h + a] >= 0) chords.add(d.chordOf[3 * h + a]);
          }
      changedSheets = [...sheets].sort((x, y) => x - y);
      changedChords = [...chords].sort((x, y) => x - y);
    }
    // The engine's own facts about a single step: its inverse and the geometry it left.
    const facts = result && typeof result === 'object' && 'inverse' in result
      ? { inverse: result.inverse, noInverse: result.noInverse ?? null, quality: result.quality ?? null }
      : { inverse: null, noInverse: null, quality: null };
    return { key: meshKey, step, created, removed, changedSheets, changedChords, ...facts };
  }

  const engine = {
    revision: 0,
    /** A fresh start mesh; file meshes keep their bytes so the timeline can replay. */
    start(spec, bytes = null) {
      if (spec.kind === 'file') fileBytes = bytes;
      const t = performance.now();
      const mesh = build(spec);
      engine.buildMs = performance.now() - t;
      serial++;
      setMesh(mesh, { spec, steps: [], at: 0, report: null });
    },
    hexDual() {
      const s = store.get();
      if (!hd || hdKey !== s.meshKey) {
        hd = hexDualOf(s.mesh);
        hdKey = s.meshKey;
      }
      return hd;
    },
    /** Applies one step at the current position; later (undone) steps are dropped. Throws on error. */
    applyStep(step) {
      const s = store.get();
      const before = engine.hexDual();
      const result = s.mesh.apply(step);
      const after = hexDualOf(s.mesh);
      const steps = [...s.steps.slice(0, s.at), step];
      const at = steps.length;
      const meshKey = key(s.mesh, at);
      hd = after;
      hdKey = meshKey;
      store.set({ steps, at, meshKey, report: diffReport(before, after, result, step, meshKey), quality: s.colorBy === 'quality' ? s.mesh.quality() : null });
    },
    /**
     * Applies cubical flip `name` to `hexes` as its verified atomic steps, which join the timeline
     * like typed steps (so the URL replays them). Throws on error, leaving the mesh unchanged.
     */
    applyFlip(name, hexes) {
      const s = store.get();
      const before = engine.hexDual();
      const reports = s.mesh.flip(name, hexes, { viaAtomic: true });
      const after = hexDualOf(s.mesh);
      const steps = [...s.steps.slice(0, s.at), ...reports.map((r) => r.step)];
      const meshKey = key(s.mesh, steps.length);
      hd = after;
      hdKey = meshKey;
      const label = `flip ${name} at ${hexes.map((h) => 'h' + h).join(' ')} (${reports.length} steps)`;
      store.set({ steps, at: steps.length, meshKey, report: diffReport(before, after, null, label, meshKey), quality: s.colorBy === 'quality' ? s.mesh.quality() : null });
    },
    /**
     * Applies an operation log ('v1;...' or its URL form) at the current position, all or nothing
     * (on an error no step of it stays applied and the error is thrown); its steps join the timeline.
     */
    applyLog(log) {
      const s = store.get();
      const before = engine.hexDual();
      const reports = s.mesh.applyLog(log);
      const after = hexDualOf(s.mesh);
      const steps = [...s.steps.slice(0, s.at), ...reports.map((r) => r.step)];
      const meshKey = key(s.mesh, steps.length);
      hd = after;
      hdKey = meshKey;
      const label = `log of ${reports.length} step${reports.length === 1 ? '' : 's'}`;
      store.set({ steps, at: steps.length, meshKey, report: diffReport(before, after, null, label, meshKey), quality: s.colorBy === 'quality' ? s.mesh.quality() : null });
    },
    /** Moves to step k of the current list (0 = the start mesh). */
    goTo(k) {
      const s = store.get();
      if (k === s.at + 1) {
        const steps = s.steps;
        engine.applyStep(s.steps[s.at]);
        store.set({ steps });
        return;
      }
      const before = engine.hexDual();
      if (k === s.at - 1 && typeof s.mesh.undo === 'function') {
        s.mesh.undo();
        const after = hexDualOf(s.mesh);
        const meshKey = key(s.mesh, k);
        hd = after;
        hdKey = meshKey;
        store.set({ at: k, meshKey, report: diffReport(before, after, null, `undo ${s.steps[k]}`, meshKey), quality: s.colorBy === 'quality' ? s.mesh.quality() : null });
        return;
      }
      const mesh = build(s.spec);
      for (let i = 0; i < k; i++) mesh.apply(s.steps[i]);
      const after = hexDualOf(mesh);
      setMesh(mesh, { at: k, steps: s.steps });
      const t = store.get();
      hd = after;
      hdKey = t.meshKey;
      const step = k < s.at ? `back to step ${k}` : `forward to step ${k}`;
      store.set({ report: diffReport(before, after, null, step, t.meshKey) });
    },
    /**
     * Replays a URL's steps on the fresh start mesh up to `at` (all when null). Returns '' or a message
     * naming the first step that failed (it and the later steps are dropped).
     */
    replay(steps, at) {
      const s = store.get();
      const stop = at === null || at === undefined ? steps.length : Math.min(at, steps.length);
      const before = stop > 0 ? hexDualOf(s.mesh) : null;
      // What the replayed steps changed, for the timeline and the lists; textOnly: the 3D view shows
      // the mesh as a fresh load does (no ghosts, no dimming, no motion).
      const replayed = (n, meshKey) => {
        const after = hexDualOf(s.mesh);
        hd = after;
        hdKey = meshKey;
        return { ...diffReport(before, after, null, `replayed ${n} step${n === 1 ? '' : 's'} from the link`, meshKey), textOnly: true };
      };
      for (let i = 0; i < stop; i++) {
        try {
          s.mesh.apply(steps[i]);
        } catch (e) {
          const meshKey = key(s.mesh, i);
          store.set({ steps: steps.slice(0, i), at: i, meshKey, report: i > 0 ? replayed(i, meshKey) : null });
          return `ignored steps from step ${i + 1} (${steps[i]}): ${e.message}`;
        }
      }
      if (stop === 0) {
        hd = null;
        store.set({ steps: [...steps], at: 0 });
        return '';
      }
      const meshKey = key(s.mesh, stop);
      store.set({ steps: [...steps], at: stop, meshKey, report: replayed(stop, meshKey) });
      return '';
    },
    fileBytes: () => fileBytes,
  };
  return engine;
}
