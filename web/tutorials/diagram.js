// A sheet diagram (TK03 §1.1) as responsive SVG from the engine's layout: boundary loops, chords
// in their own colour (as in 3D), crossings (= hexes) labelled with hex ids, a cut-open sheet's
// seams. Hovering a crossing reports its hex, clicking picks it; `mark(hex)` outlines the crossings
// of a hex, `select(hexes)` rings the picked ones. A redraw of the same sheet after a step is
// animated (diagramMotion.js): crossings move, new ones fade in, the old drawing fades out.
import { chordColor } from '../colors.js';
import { animateDiagram, crossingKey, crossingPlaces } from '../diagramMotion.js';
import { diagramFrame } from '../diagramFrame.js';

const NS = 'http://www.w3.org/2000/svg';

function el(name, attrs, parent) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (parent) parent.appendChild(e);
  return e;
}

const points = (pts) => pts.map((p) => p.join(',')).join(' ');

function drawFrame(g, d) {
  if (d.local) el('circle', { cx: 0, cy: 0, r: 1, fill: 'none', stroke: '#666', 'stroke-width': 0.01, 'stroke-dasharray': '0.04 0.03' }, g);
  d.loops.forEach((loop, i) =>
    el('polygon', { points: points(loop), fill: i === 0 ? '#f4f6fa' : 'white', stroke: '#222', 'stroke-width': d.local ? 0.006 : 0.012 }, g),
  );
  // A sheet cut open into a polygon: each seam is drawn on two sides, labelled alike.
  for (const a of d.arcs || []) {
    if (a.pair < 0) continue;
    el('polyline', { points: points(a.points), fill: 'none', stroke: '#555', 'stroke-width': 0.03, 'stroke-dasharray': '0.06 0.03' }, g);
    const mid = a.points[Math.floor(a.points.length / 2)];
    const t = el('text', { x: mid[0] * 1.08, y: -mid[1] * 1.08, 'font-size': 0.09, 'font-weight': 700, transform: 'scale(1,-1)', 'text-anchor': 'middle' }, g);
    t.textContent = a.label;
  }
  const chords = el('g', { class: 'chords' }, g);
  for (const c of d.chords) {
    el('polyline', { points: points(c.points), fill: 'none', stroke: chordColor(c.id), 'stroke-width': 0.026, 'data-chord': c.id, 'data-closed': c.closed ? 1 : 0, 'data-hexes': c.hexes.join(' '), 'stroke-linejoin': 'round' }, chords);
  }
  for (const b of d.boundary) el('rect', { x: b.x - 0.018, y: b.y - 0.018, width: 0.036, height: 0.036, fill: '#222' }, g);
  return chords;
}

export function createDiagram(container, { onHover, onPick } = {}) {
  const box = document.createElement('div');
  box.className = 'diagram';
  container.appendChild(box);
  let svg = null, shown = null, motion = null;

  // The crossings as circles with labels, each pair in a group placed by `place`.
  function drawCrossings(g, d, created) {
    const r = d.crossings.length > 60 ? 0.02 : 0.034;
    const font = d.crossings.length > 60 ? 0.05 : 0.08;
    return d.crossings.map((c) => {
      const key = crossingKey(c);
      const fill = created.has(c.hex) ? '#ff9d5c' : c.outside ? '#fc6' : 'white';
      const dot = el('circle', { cx: c.x, cy: c.y, r, fill, stroke: '#111', 'stroke-width': 0.008, 'data-hex': c.hex, 'data-key': key, class: 'crossing' }, g);
      el('title', {}, dot).textContent = `hex ${c.hex}`;
      dot.addEventListener('pointerenter', () => onHover?.(c.hex));
      dot.addEventListener('pointerleave', () => onHover?.(-1));
      dot.addEventListener('click', (e) => onPick?.(c.hex, e));
      const t = el('text', { 'font-size': font, transform: 'scale(1,-1)', 'data-key': key, class: 'label' }, g);
      t.textContent = String(c.hex);
      const place = (x, y) => {
        dot.setAttribute('cx', x);
        dot.setAttribute('cy', y);
        t.setAttribute('x', x + r + 0.01);
        t.setAttribute('y', -(y + r));
      };
      place(c.x, c.y);
      return { key, x: c.x, y: c.y, place, els: [dot, t] };
    });
  }

  /** Draws diagram `d`; `animate` moves from the previous drawing when it showed the same sheet. */
  function draw(d, { title = '', created = new Set(), animate = false } = {}) {
    motion?.cancel();
    const old = animate && shown && shown.sheet === d.sheet && svg ? { places: crossingPlaces(shown), g: svg.querySelector('g.drawing') } : null;
    box.replaceChildren();
    shown = d;
    const f = diagramFrame(d);
    svg = el('svg', { viewBox: `${f.cx - f.half} ${-f.cy - f.half} ${2 * f.half} ${2 * f.half}`, role: 'img', 'data-sheet': d.sheet, 'data-method': d.method }, box);
    el('title', {}, svg).textContent = title || `sheet ${d.sheet}: ${d.topology}`;
    if (old?.g) svg.appendChild(old.g).classList.add('ghost');
    const g = el('g', { transform: 'scale(1,-1)', class: 'drawing' }, svg);
    const chords = drawFrame(g, d);
    const items = drawCrossings(g, d, created);
    if (d.note) box.append(Object.assign(document.createElement('p'), { className: 'diagram-note', textContent: d.note }));
    motion = old ? animateDiagram({ old: old.places, ghost: old.g, items, fadeIn: [chords] }) : null;
  }

  return {
    element: box,
    draw,
    get animating() {
      return !!motion?.running;
    },
    message(text) {
      motion?.cancel();
      box.replaceChildren(Object.assign(document.createElement('p'), { className: 'diagram-note', textContent: text }));
      svg = null;
      shown = null;
    },
    /** Outlines the crossings of one hex (hover). */
    mark(hex) {
      if (!svg) return;
      for (const c of svg.querySelectorAll('g.drawing circle.crossing')) c.classList.toggle('hot', Number(c.dataset.hex) === hex);
    },
    /** Rings the crossings of these hexes (the pick). */
    select(hexes) {
      if (!svg) return;
      const set = new Set(hexes);
      for (const c of svg.querySelectorAll('g.drawing circle.crossing')) c.classList.toggle('picked', set.has(Number(c.dataset.hex)));
    },
    /** Page position of the (first) crossing of a hex, for tests and hints. */
    crossingAt(hex) {
      const c = svg?.querySelector(`g.drawing circle.crossing[data-hex="${hex}"]`);
      if (!c) return null;
      const r = c.getBoundingClientRect();
      return { x: r.left + r.width / 2, y: r.top + r.height / 2 };
    },
  };
}
