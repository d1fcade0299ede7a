// The side panel: mesh chooser, counts, and the sheet / chord pickers.
import { sheetColor, chordColor } from './colors.js';

export function createPanel(root, actions) {
  const $ = (sel) => root.querySelector(sel);
  $('#mesh-build').addEventListener('click', () => actions.build($('#mesh-kind').value, $('#mesh-dims').value));
  $('#mesh-dims').addEventListener('keydown', (e) => {
    if (e.key === 'Enter') actions.build($('#mesh-kind').value, $('#mesh-dims').value);
  });
  $('#mesh-file').addEventListener('change', async (e) => {
    const file = e.target.files[0];
    if (file) actions.open(new Uint8Array(await file.arrayBuffer()), file.name);
  });
  $('#shrink').addEventListener('input', (e) => actions.shrink(Number(e.target.value)));
  $('#op-apply').addEventListener('click', () => actions.apply($('#op-step').value.trim()));
  $('#op-step').addEventListener('keydown', (e) => {
    if (e.key === 'Enter') actions.apply($('#op-step').value.trim());
  });
  $('#op-undo').addEventListener('click', () => actions.undo());
  $('#flip-load').addEventListener('click', () => actions.loadFlip($('#flip-name').value));
  $('#flip-step').addEventListener('click', () => actions.stepFlip());
  const flipSelect = $('#flip-name');
  for (const f of actions.flips) {
    const o = document.createElement('option');
    o.value = f.name;
    o.textContent = f.steps ? `${f.name} (${f.steps.length} steps)` : `${f.name} (none found)`;
    o.disabled = !f.steps;
    flipSelect.appendChild(o);
  }

  function fillPicker(list, items, kind, selection, describe) {
    list.replaceChildren(
      ...items.map((item) => {
        const li = document.createElement('li');
        li.dataset.kind = kind;
        li.dataset.id = item.id;
        if (selection && selection.kind === kind && selection.id === item.id) li.classList.add('selected');
        const sw = document.createElement('span');
        sw.className = 'swatch';
        sw.style.background = kind === 'sheet' ? sheetColor(item.id) : chordColor(item.id);
        const text = document.createElement('span');
        text.innerHTML = `${kind} ${item.id} <span class="tag">${describe(item)}</span>`;
        li.append(sw, text);
        li.addEventListener('click', () => actions.select({ kind, id: item.id }));
        return li;
      }),
    );
  }

  let shownMesh = null;
  return {
    update(state) {
      $('#error').textContent = state.error || '';
      if (state.meshSpec && state.meshSpec.kind !== 'file') {
        $('#mesh-kind').value = state.meshSpec.kind;
        $('#mesh-dims').value = state.meshSpec.dims.join('x');
      }
      const fq = state.flipQueue;
      $('#flip-status').textContent = fq
        ? `${fq.name}: ${fq.done} of ${fq.steps.length} steps applied` + (fq.done < fq.steps.length ? ` — next: ${fq.steps[fq.done]}` : ' — the after side')
        : 'Load a flip to step through its atomic decomposition on the 4-cube boundary.';
      $('#flip-step').disabled = !fq || fq.done >= fq.steps.length;
      $('#shrink').value = String(state.shrink);
      if (!state.mesh) return;
      $('#ops-log').replaceChildren(
        ...state.ops.map((o) => Object.assign(document.createElement('li'), { textContent: o.step })),
      );
      $('#op-undo').disabled = state.ops.length === 0;
      const info = state.mesh.info();
      for (const td of root.querySelectorAll('[data-count]')) td.textContent = String(info[td.dataset.count]);
      $('#sheet-count').textContent = `(${info.sheets.length})`;
      $('#chord-count').textContent = `(${info.chords.length})`;
      {
        fillPicker($('#sheets'), info.sheets, 'sheet', state.selection, (s) =>
          `${s.hexes} hexes · ${s.topology}${s.boundaryLoops ? ` · ${s.boundaryLoops} loop${s.boundaryLoops > 1 ? 's' : ''}` : ''}${s.selfIntersecting ? ' · self-intersecting' : ''}`,
        );
        fillPicker($('#chords'), info.chords, 'chord', state.selection, (c) =>
          `${c.hexes} hexes · ${c.closed ? 'closed' : 'open'}${c.selfIntersecting ? ' · self-intersecting' : ''}`,
        );
        shownMesh = state.mesh;
      }
      const label = document.getElementById('selection-label');
      if (state.selection) {
        const { kind, id } = state.selection;
        const item = (kind === 'sheet' ? info.sheets : info.chords)[id];
        label.textContent = item ? `${kind} ${id}: ${item.hexes} hexes` : '';
      } else {
        label.textContent = `${info.hexes} hexes — pick a sheet or chord`;
      }
    },
  };
}
