// The flips view: choose a flip; its before side is highlighted in the 4-cube boundary (the rest
// dimmed), the after side is drawn next to it, and the verified atomic decomposition is loaded
// into the timeline so ◀ ▶ (and ←/→) step through it, each step named with its effect.
import { Mesh } from '../wasm/index.js';
import { createView3d } from './view3d.js';

export function createFlipsView(root, actions, store) {
  root.innerHTML = `<div class="flip-card"><div class="row"><b>Flip</b><select id="flip-name" aria-label="flip"></select><button id="flip-load">Load</button></div>
    <div id="flip-desc" class="lede"></div><ol id="flip-steps" class="flip-steps"></ol><div id="flip-status" class="lede"></div>
    <div class="row"><input id="flip-at" class="mono" placeholder="hexes: h0 h1 …" size="16" aria-label="flip place" /><button id="flip-apply">Apply in my mesh</button></div></div>
    <div class="flip-after"><span class="label">after</span></div>`;
  const $ = (s) => root.querySelector(s);
  const select = $('#flip-name');
  for (const f of actions.flips) {
    const o = document.createElement('option');
    o.value = f.name;
    o.textContent = f.steps ? `${f.name} (${f.steps.length} steps)` : `${f.name} (no decomposition)`;
    o.disabled = !f.steps;
    select.appendChild(o);
  }
  let afterView = null, afterMesh = null, afterFor = null;

  function load(name) {
    const f = actions.flips.find((x) => x.name === name);
    if (!f || !f.steps) return actions.set({ error: `no stored decomposition for ${name}` });
    store.batch(() => {
      actions.engine.start({ kind: 'fourcube', dims: [] });
      const s = store.get();
      store.set({ steps: [...f.steps], at: 0, flip: name, view: 'flips', selection: null, diagrams: [], camera: null, error: '',
        focus: { key: `${name}:${s.meshKey}`, hexes: [...f.before] } });
    });
  }
  $('#flip-load').addEventListener('click', () => load(select.value));
  $('#flip-apply').addEventListener('click', () => {
    const hexes = ($('#flip-at').value.match(/\d+/g) || []).map(Number);
    actions.applyFlip(select.value, hexes);
  });

  function showAfter(f) {
    if (afterFor === f.name) return;
    afterFor = f.name;
    afterMesh?.delete();
    afterMesh = Mesh.fourCube();
    for (const step of f.steps) afterMesh.apply(step);
    afterView ??= createView3d(root.querySelector('.flip-after'));
    const created = [];
    const hd = afterMesh.hexDual();
    for (let h = 8; 3 * h < hd.sheetOf.length; h++) if (hd.sheetOf[3 * h] >= 0) created.push(h);
    afterView.update({ mesh: afterMesh, meshKey: `after-${f.name}:0`, shrink: 0.15, selection: null, report: null, colorBy: 'plain',
      overlay: false, ghosts: false, focus: { key: f.name, hexes: created } });
  }

  let shown = null;
  return {
    update(s) {
      if (s.view !== 'flips') return;
      const f = actions.flips.find((x) => x.name === s.flip && x.steps);
      if (!f) {
        $('#flip-desc').textContent = 'Choose a flip and press Load: its atomic decomposition steps through the timeline below (◀ ▶, ←/→).';
        return;
      }
      select.value = f.name;
      const key = `${f.name}|${s.at}|${s.steps.length}|${s.report?.key}`;
      if (key === shown) return;
      shown = key;
      if (!$('#flip-at').value && f.before) $('#flip-at').value = f.before.map((h) => 'h' + h).join(' ');
      $('#flip-desc').textContent = `${f.name}: ${f.description} (inverse ${f.inverse}${f.geometric ? ', geometric' : ''}). Before side: hexes ${f.before.join(', ')} of the 4-cube boundary (blue).`;
      $('#flip-steps').replaceChildren(
        ...f.steps.map((st, i) => {
          const li = document.createElement('li');
          li.textContent = st;
          if (i === s.at - 1) li.classList.add('current');
          return li;
        }),
      );
      const r = s.report && s.report.key === s.meshKey ? s.report : null;
      $('#flip-status').textContent =
        s.at === 0 ? `before side; ${f.steps.length} steps to the after side` :
        `step ${s.at} of ${f.steps.length}: ${s.steps[s.at - 1]}${r ? ` — +${r.created.length} / −${r.removed.length} hexes, sheets ${r.changedSheets.join(', ') || '–'}` : ''}${s.at === f.steps.length ? ' — the after side' : ''}`;
      showAfter(f);
    },
  };
}
