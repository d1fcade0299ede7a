// A sheet diagram (TK03 §1.1) as responsive SVG from the engine's layout: boundary loops, chords
// in their own colour (as in 3D), crossings (= hexes) labelled with hex ids, a cut-open sheet's seams. Hovering a crossing
// reports its hex; `mark(hexId)` outlines the crossings of a hex.
import { chordColor } from '../colors.js';

const NS = 'http://www.w3.org/2000/svg';

function el(name, attrs, parent) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (parent) parent.appendChild(e);
  return e;
}

export function createDiagram(container, { onHover } = {}) {
  const box = document.createElement('div');
  box.className = 'diagram';
  container.appendChild(box);
  let svg = null;

  function draw(d, { title = '', created = new Set() } = {}) {
    box.replaceChildren();
    const m = d.openedHex !== null && d.openedHex !== undefined ? 1.6 : 1.15;
    svg = el('svg', { viewBox: `${-m} ${-m} ${2 * m} ${2 * m}`, role: 'img', 'data-sheet': d.sheet }, box);
    el('title', {}, svg).textContent = title || `sheet ${d.sheet}: ${d.topology}`;
    const g = el('g', { transform: 'scale(1,-1)' }, svg);
    if (d.local) el('circle', { cx: 0, cy: 0, r: 1, fill: 'none', stroke: '#666', 'stroke-width': 0.01, 'stroke-dasharray': '0.04 0.03' }, g);
    d.loops.forEach((loop, i) =>
      el('polygon', { points: loop.map((p) => p.join(',')).join(' '), fill: i === 0 ? '#f4f6fa' : 'white', stroke: '#222', 'stroke-width': d.local ? 0.006 : 0.012 }, g),
    );
    // A sheet cut open into a polygon: each seam is drawn on two sides, labelled alike.
    for (const a of d.arcs || []) {
      if (a.pair < 0) continue;
      el('polyline', { points: a.points.map((p) => p.join(',')).join(' '), fill: 'none', stroke: '#555', 'stroke-width': 0.03, 'stroke-dasharray': '0.06 0.03' }, g);
      const mid = a.points[Math.floor(a.points.length / 2)];
      const t = el('text', { x: mid[0] * 1.08, y: -mid[1] * 1.08, 'font-size': 0.09, 'font-weight': 700, transform: 'scale(1,-1)', 'text-anchor': 'middle' }, g);
      t.textContent = a.label;
    }
    for (const c of d.chords) {
      el('polyline', {
        points: c.points.map((p) => p.join(',')).join(' '), fill: 'none', stroke: chordColor(c.id),
        'stroke-width': 0.026, 'data-chord': c.id, 'stroke-linejoin': 'round',
      }, g);
    }
    for (const b of d.boundary) el('rect', { x: b.x - 0.018, y: b.y - 0.018, width: 0.036, height: 0.036, fill: '#222' }, g);
    const r = d.crossings.length > 60 ? 0.02 : 0.034;
    const font = d.crossings.length > 60 ? 0.05 : 0.08;
    for (const c of d.crossings) {
      const fill = created.has(c.hex) ? '#ff9d5c' : c.outside ? '#fc6' : 'white';
      const dot = el('circle', { cx: c.x, cy: c.y, r, fill, stroke: '#111', 'stroke-width': 0.008, 'data-hex': c.hex, class: 'crossing' }, g);
      el('title', {}, dot).textContent = `hex ${c.hex}`;
      dot.addEventListener('pointerenter', () => onHover?.(c.hex));
      dot.addEventListener('pointerleave', () => onHover?.(-1));
      const t = el('text', { x: c.x + r + 0.01, y: -(c.y + r), 'font-size': font, transform: 'scale(1,-1)' }, g);
      t.textContent = String(c.hex);
    }
    if (d.note) box.append(Object.assign(document.createElement('p'), { className: 'diagram-note', textContent: d.note }));
  }

  return {
    element: box,
    draw,
    message(text) {
      box.replaceChildren(Object.assign(document.createElement('p'), { className: 'diagram-note', textContent: text }));
      svg = null;
    },
    mark(hex) {
      if (!svg) return;
      for (const c of svg.querySelectorAll('circle.crossing')) c.classList.toggle('hot', Number(c.dataset.hex) === hex);
    },
  };
}
