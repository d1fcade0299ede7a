// The sheet diagram of the selected sheet, drawn as SVG from the engine's JSON. Clicking a chord
// selects it (and highlights its hexes in 3D); the selected chord is drawn thicker.
import { chordColor } from './colors.js';

const NS = 'http://www.w3.org/2000/svg';

function el(name, attrs, parent) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (parent) parent.appendChild(e);
  return e;
}

export function createSheetDiagram(container, actions) {
  const box = document.createElement('div');
  box.id = 'diagram';
  container.appendChild(box);

  function draw(d, selection) {
    box.replaceChildren();
    const title = document.createElement('div');
    title.className = 'diagram-title';
    title.textContent = `sheet ${d.sheet} · ${d.topology}${d.method !== d.topology ? ` · ${d.method}` : ''}`;
    box.appendChild(title);
    const m = d.openedHex !== null ? 1.6 : 1.15;
    const svg = el('svg', { viewBox: `${-m} ${-m} ${2 * m} ${2 * m}`, width: 300, height: 300, 'data-sheet': d.sheet }, box);
    const g = el('g', { transform: 'scale(1,-1)' }, svg);
    if (d.local) el('circle', { cx: 0, cy: 0, r: 1, fill: 'none', stroke: '#666', 'stroke-width': 0.01, 'stroke-dasharray': '0.04 0.03' }, g);
    d.loops.forEach((loop, i) =>
      el('polygon', {
        points: loop.map((p) => p.join(',')).join(' '),
        fill: i === 0 ? '#f4f6fa' : 'white',
        stroke: '#222',
        'stroke-width': d.local ? 0.006 : 0.012,
      }, g),
    );
    for (const c of d.chords) {
      const selected = selection && selection.kind === 'chord' && selection.id === c.id;
      const line = el('polyline', {
        points: c.points.map((p) => p.join(',')).join(' '),
        fill: 'none',
        stroke: chordColor(c.id),
        'stroke-width': selected ? 0.05 : 0.022,
        'data-chord': c.id,
        class: 'chord',
      }, g);
      line.addEventListener('click', () => actions.select({ kind: 'chord', id: c.id }, { keepDiagram: true }));
      el('title', {}, line).textContent = `chord ${c.id} (with sheet ${c.otherSheet})${c.closed ? ', closed' : ''}`;
    }
    for (const b of d.boundary) el('rect', { x: b.x - 0.015, y: b.y - 0.015, width: 0.03, height: 0.03, fill: '#222' }, g);
    for (const c of d.crossings) {
      el('circle', { cx: c.x, cy: c.y, r: 0.028, fill: c.outside ? '#fc6' : 'white', stroke: '#111', 'stroke-width': 0.008, 'data-hex': c.hex }, g);
      const t = el('text', { x: c.x + 0.035, y: -(c.y + 0.03), 'font-size': 0.075, transform: 'scale(1,-1)' }, g);
      t.textContent = String(c.hex);
    }
    if (d.note) {
      const note = document.createElement('div');
      note.className = 'diagram-note';
      note.textContent = d.note;
      box.appendChild(note);
    }
  }

  return {
    update(state) {
      if (!state.mesh || state.diagramSheet === null || state.diagramSheet === undefined) {
        box.hidden = true;
        return;
      }
      box.hidden = false;
      try {
        draw(state.mesh.sheetDiagram(state.diagramSheet), state.selection);
      } catch (e) {
        box.replaceChildren(Object.assign(document.createElement('div'), { className: 'diagram-note', textContent: e.message }));
      }
    },
  };
}
