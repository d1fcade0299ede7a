// The side panel: mesh chooser, selection info, view toggles, quality histogram, counts and the
// sheet / chord lists (filterable, virtualized: only visible rows exist in the DOM). Also the
// hover tip over the 3D view.
import { sheetColor, chordColor } from './colors.js';
import { formatSelection, dualThrough } from './selection.js';
import { qualityRgb } from './paint.js';
import { singularColor } from './view3d/overlays.js';

const ROW = 22;

function describeSheet(s) {
  return `${s.hexes} hexes · ${s.topology}${s.boundaryLoops ? ` · ${s.boundaryLoops} loop${s.boundaryLoops > 1 ? 's' : ''}` : ''}${s.selfIntersecting ? ' · self-intersecting' : ''}`;
}
function describeChord(c) {
  return `${c.hexes} hexes · ${c.closed ? 'closed' : 'open'}${c.selfIntersecting ? ' · self-intersecting' : ''}`;
}

/** A virtualized, filterable list of sheets or chords. */
function createList(box, filterInput, kind, actions) {
  let items = [], shown = [], changed = new Set(), selected = -1;
  const spacer = document.createElement('div');
  box.appendChild(spacer);
  const describe = kind === 'sheet' ? describeSheet : describeChord;

  function matches(item, q) {
    if (!q) return true;
    if (/^\d+$/.test(q)) return String(item.id).startsWith(q);
    if (q === 'changed') return changed.has(item.id);
    return describe(item).includes(q);
  }
  function draw() {
    const top = box.scrollTop, h = box.clientHeight || 200;
    const first = Math.max(0, Math.floor(top / ROW) - 5), last = Math.min(shown.length, Math.ceil((top + h) / ROW) + 5);
    spacer.style.height = `${shown.length * ROW}px`;
    const rows = [];
    for (let i = first; i < last; i++) {
      const item = shown[i];
      const div = document.createElement('div');
      div.className = 'row-item';
      if (item.id === selected) div.classList.add('selected');
      if (changed.has(item.id)) div.classList.add('changed');
      div.style.top = `${i * ROW}px`;
      div.dataset.kind = kind;
      div.dataset.id = item.id;
      const sw = document.createElement('span');
      sw.className = 'swatch';
      sw.style.background = kind === 'sheet' ? sheetColor(item.id) : chordColor(item.id);
      const text = document.createElement('span');
      text.innerHTML = `${kind} ${item.id} <span class="tag">${describe(item)}</span>`;
      div.append(sw, text);
      rows.push(div);
    }
    box.replaceChildren(spacer, ...rows);
  }
  box.addEventListener('scroll', draw);
  box.addEventListener('click', (e) => {
    const row = e.target.closest('.row-item');
    if (!row) return;
    const id = Number(row.dataset.id);
    actions.select({ kind, id });
    if (kind === 'sheet') actions.toggleDiagram(id);
  });
  filterInput.addEventListener('input', () => {
    refilter();
    draw();
  });
  function refilter() {
    const q = filterInput.value.trim();
    shown = items.filter((it) => matches(it, q));
  }
  return {
    set(newItems, newChanged, sel) {
      items = newItems;
      changed = newChanged;
      selected = sel;
      refilter();
      draw();
      // Bring the selected row into view.
      const i = shown.findIndex((x) => x.id === sel);
      if (i >= 0 && (i * ROW < box.scrollTop || (i + 1) * ROW > box.scrollTop + box.clientHeight)) {
        box.scrollTop = Math.max(0, i * ROW - 60);
        draw();
      }
    },
    get rendered() {
      return box.querySelectorAll('.row-item').length;
    },
  };
}

function histogram(root, quality, mesh) {
  if (!quality) return root.replaceChildren();
  const bins = new Array(20).fill(0);
  let inverted = 0, n = 0;
  const sj = quality.scaledJacobian;
  const hd = mesh.hexDual();
  for (let h = 0; h < sj.length; h++) {
    if (hd.sheetOf[3 * h] < 0) continue;
    n++;
    if (sj[h] <= 0) inverted++;
    bins[Math.min(19, Math.max(0, Math.floor(((sj[h] + 1) / 2) * 20)))]++;
  }
  const max = Math.max(1, ...bins);
  const w = 290, hgt = 60;
  const bars = bins
    .map((b, i) => {
      const x = (i * w) / 20, bh = (b / max) * (hgt - 14);
      const c = qualityRgb(-1 + (i + 0.5) / 10);
      return `<rect x="${x}" y="${hgt - 12 - bh}" width="${w / 20 - 1}" height="${bh}" fill="rgb(${c})"><title>${(-1 + i / 10).toFixed(1)}..${(-0.9 + i / 10).toFixed(1)}: ${b}</title></rect>`;
    })
    .join('');
  root.innerHTML = `<svg width="${w}" height="${hgt}" role="img" aria-label="scaled Jacobian histogram">${bars}<text x="0" y="${hgt - 1}" font-size="10">-1</text><text x="${w / 2 - 4}" y="${hgt - 1}" font-size="10">0</text><text x="${w - 8}" y="${hgt - 1}" font-size="10">1</text></svg>
    <div class="mono" id="quality-summary">min ${quality.min.toFixed(3)} · max ${quality.max.toFixed(3)} · ${n} hexes · <b style="color:${inverted ? '#d600aa' : '#2b7'}">${inverted} inverted</b>${inverted ? `: ${[...quality.inverted.slice(0, 8)].map((h) => 'h' + h).join(' ')}${quality.inverted.length > 8 ? ' …' : ''}` : ''}</div>`;
}

// The singularity graph's counts, with a swatch per kind and valence as the 3D view colours them.
function singularSummary(root, sing) {
  if (!sing) return root.replaceChildren();
  const c = sing.counts;
  const chip = (boundary, valence, n) => {
    const color = singularColor({ boundary, valence: Number(valence) });
    return `<span class="chip"><span class="swatch" style="background:${color}"></span>${boundary ? 'boundary' : 'interior'} valence ${valence}: ${n}</span>`;
  };
  const chips = [
    ...Object.entries(c.interiorByValence).map(([v, n]) => chip(false, v, n)),
    ...Object.entries(c.boundaryByValence).map(([v, n]) => chip(true, v, n)),
  ];
  root.innerHTML = `<div>${c.interiorEdges} interior and ${c.boundaryEdges} boundary singular edges · ${c.curves} curves · ${c.vertices} irregular vertices (${c.boundaryVertices} on the boundary)</div>${chips.join(' ')}`;
}

export function createPanel(root, actions, view) {
  const $ = (sel) => document.querySelector(sel);
  const build = () => actions.build($('#mesh-kind').value, $('#mesh-dims').value);
  let shownSpec = null; // the mesh spec the chooser shows (set from the state only when it changes)
  $('#mesh-build').addEventListener('click', build);
  // Leaving a file's entry for a generator: its dimensions and Build come back.
  $('#mesh-kind').addEventListener('change', (e) => {
    const generator = e.target.value !== 'file';
    $('#mesh-dims').hidden = $('#mesh-build').hidden = !generator;
  });
  $('#mesh-dims').addEventListener('keydown', (e) => e.key === 'Enter' && build());
  $('#mesh-file').addEventListener('change', (e) => actions.openFiles([...e.target.files]));
  $('#shrink').addEventListener('input', (e) => actions.set({ shrink: Number(e.target.value) }));
  $('#overlay').addEventListener('change', (e) => actions.set({ overlay: e.target.checked }));
  $('#ghosts').addEventListener('change', (e) => actions.set({ ghosts: e.target.checked }));
  $('#focus-changes').addEventListener('change', (e) => actions.set({ focusChanges: e.target.checked }));
  $('#singular').addEventListener('change', (e) => actions.set({ singular: e.target.checked }));
  $('#quality').addEventListener('change', (e) => {
    const on = e.target.checked;
    const mesh = window.hexdual.store.get().mesh;
    actions.set({ colorBy: on ? 'quality' : 'plain', quality: on ? mesh.quality() : null });
  });
  // One slice per animation frame: a big mesh rebuilds its shell for each position of the slider.
  let sliceFrame = 0;
  const slice = () => {
    cancelAnimationFrame(sliceFrame);
    sliceFrame = requestAnimationFrame(() => {
      const axis = $('#slice-axis').value;
      actions.set({ slice: axis === '' ? null : { axis: Number(axis), at: Number($('#slice-at').value) } });
    });
  };
  $('#slice-axis').addEventListener('change', slice);
  $('#slice-at').addEventListener('input', slice);
  $('#pick-mode').addEventListener('change', (e) => (view.pickMode = e.target.value));
  $('#open-sheets').addEventListener('click', () => actions.openSheetsOfSelection());
  $('#clear-sel').addEventListener('click', () => actions.select(null));
  for (const b of document.querySelectorAll('.tabs button')) b.addEventListener('click', () => actions.set({ view: b.dataset.view }));

  const sheets = createList($('#sheets'), $('#sheet-filter'), 'sheet', actions);
  const chords = createList($('#chords'), $('#chord-filter'), 'chord', actions);
  const tip = $('#tip');
  let shownKey = null, qualityKey = null, singularKey = null;

  function describeSelection(s, sel) {
    if (!sel && s.waitingFor) return `a 3×3×3 grid stands in: open or drop ${s.waitingFor} to replay the shared steps`;
    if (!sel) return `${s.mesh.counts.hexes} hexes — click a quad, an edge, or a sheet`;
    const id = formatSelection(sel);
    if (sel.kind === 'sheet') {
      const it = s.mesh.sheets[sel.id];
      return it ? `sheet ${sel.id}: ${it.hexes} hexes` : id;
    }
    if (sel.kind === 'chord') {
      const it = s.mesh.chords[sel.id];
      return it ? `chord ${sel.id}: ${it.hexes} hexes` : id;
    }
    const d = dualThrough(sel, actions.engine.hexDual());
    const what = sel.kind === 'quad' ? 'quad' : sel.kind === 'edge' ? 'edge' : 'hex';
    if (sel.kind === 'edge') {
      // The edge's valence, and the sheet and chords through it (mesh.edgeDual).
      try {
        const e = s.mesh.edgeDual(sel.hex, sel.edge);
        const regular = e.valence === (e.boundary ? 2 : 4);
        return `edge ${id} · valence ${e.valence}${e.boundary ? ' (boundary)' : ''}${regular ? '' : ' · singular'} · sheet ${e.sheet} crosses it · chords ${e.chords.join(', ')} (sheets ${e.sheets.join(', ')})`;
      } catch {
        // fall through to the hex-dual arrays
      }
    }
    return `${what} ${id} · sheets ${d.sheets.join(', ') || '–'} · chords ${d.chords.join(', ') || '–'}`;
  }

  return {
    hover(pick, e) {
      view.setHover(pick);
      if (!pick || !e) return (tip.hidden = true);
      const s = window.hexdual.store.get();
      tip.hidden = false;
      tip.textContent = describeSelection(s, pick);
      tip.style.left = `${e.clientX + 14}px`;
      tip.style.top = `${e.clientY + 12}px`;
    },
    update(s) {
      if (!s.mesh) return;
      $('#error').textContent = s.error || '';
      $('#notice').textContent = s.notice || '';
      for (const b of document.querySelectorAll('.tabs button')) b.classList.toggle('on', b.dataset.view === s.view);
      if (s.spec && JSON.stringify(s.spec) !== shownSpec) {
        shownSpec = JSON.stringify(s.spec);
        // A file shows as its own entry ("file: NAME"); choosing a generator and Build replaces it.
        let fileOption = $('#mesh-kind option[value="file"]');
        if (s.spec.kind === 'file') {
          if (!fileOption) fileOption = $('#mesh-kind').appendChild(new Option('', 'file'));
          fileOption.textContent = `file: ${s.spec.name}`;
          $('#mesh-kind').value = 'file';
          $('#mesh-dims').hidden = $('#mesh-build').hidden = true;
        } else {
          fileOption?.remove();
          $('#mesh-kind').value = s.spec.kind;
          $('#mesh-dims').hidden = $('#mesh-build').hidden = false;
          if (s.spec.dims.length) $('#mesh-dims').value = s.spec.dims.join('x');
        }
      }
      $('#shrink').value = String(s.shrink);
      $('#overlay').checked = s.overlay;
      $('#ghosts').checked = s.ghosts;
      $('#focus-changes').checked = s.focusChanges;
      $('#quality').checked = s.colorBy === 'quality';
      $('#singular').checked = s.singular;
      const sk = s.singular ? s.meshKey : null;
      if (singularKey !== sk) {
        singularKey = sk;
        singularSummary($('#singular-summary'), s.singular ? s.mesh.singularities() : null);
      }
      $('#slice-axis').value = s.slice ? String(s.slice.axis) : '';
      if (s.slice) $('#slice-at').value = String(s.slice.at);
      const label = describeSelection(s, s.selection);
      $('#selection-info').textContent = label;
      // A sheet operation's preview names itself over the 3D view, where its hexes are highlighted.
      $('#selection-label').textContent = s.focus?.label ?? label;
      $('#open-sheets').disabled = !s.selection;
      const qk = s.colorBy === 'quality' ? s.meshKey : null;
      if (qualityKey !== qk) {
        qualityKey = qk;
        histogram($('#histogram'), s.colorBy === 'quality' ? s.quality : null, s.mesh);
      }
      const info = s.mesh.info();
      const key = `${s.meshKey}|${formatSelection(s.selection)}`;
      if (shownKey === key) return;
      shownKey = key;
      for (const td of root.querySelectorAll('[data-count]')) td.textContent = String(info[td.dataset.count]);
      $('#sheet-count').textContent = `(${info.sheets.length})`;
      $('#chord-count').textContent = `(${info.chords.length})`;
      const rep = s.report && s.report.key === s.meshKey ? s.report : null;
      sheets.set(info.sheets, new Set(rep ? rep.changedSheets : []), s.selection?.kind === 'sheet' ? s.selection.id : -1);
      chords.set(info.chords, new Set(rep ? rep.changedChords : []), s.selection?.kind === 'chord' ? s.selection.id : -1);
    },
    lists: { sheets, chords },
  };
}
