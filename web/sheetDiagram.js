// Sheet diagrams (TK03 §2): one resizable panel per open sheet, side by side. Wheel zooms, drag
// pans; labels keep a readable screen size and appear only when crossings are far enough apart
// (level of detail for 1,000-crossing sheets). Click a crossing (hex), a chord, a cell (edge) or a
// boundary mark (quad) to select it in 3D; the 3D selection is marked here. Local mode draws k rings
// around the selected hex in a dotted circle.
import { diagramFrame } from './diagramFrame.js';
import { chordColor } from './colors.js';
import { formatSelection } from './selection.js';
import { animateDiagram, crossingKey, crossingPlaces } from './diagramMotion.js';

const NS = 'http://www.w3.org/2000/svg';
const LABEL_PX = 11;

function el(name, attrs, parent) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  if (parent) parent.appendChild(e);
  return e;
}

/**
 * A crossing's label at `s` px per unit: up-right of it, or under-left of it when it would not fit
 * before the loop's right side (data-room: the room there, diagram units). Under, because the next
 * column's labels sit up-right, above the same row line.
 */
function placeLabel(t, x, y, s) {
  const left = Number(t.dataset.room) * s < 11 + 6.2 * t.textContent.length, under = left;
  t.setAttribute('x', String(left ? x - 7 / s : x + 7 / s));
  t.setAttribute('y', String(under ? -y + 14 / s : -y - 5 / s));
  t.setAttribute('text-anchor', left ? 'end' : 'start');
}

/** Per crossing, the distance to its nearest other crossing (a grid of cells; exact). */
function nearest(cs) {
  const n = cs.length;
  if (n < 2) return cs.map(() => Infinity);
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (const c of cs) x0 = Math.min(x0, c.x), x1 = Math.max(x1, c.x), y0 = Math.min(y0, c.y), y1 = Math.max(y1, c.y);
  // About one crossing per cell; never thinner than a row of them (two crossings, a line of them).
  const w = x1 - x0, h = y1 - y0;
  const cell = Math.max(Math.sqrt((w * h) / n), Math.max(w, h) / (2 * Math.sqrt(n)), 1e-9);
  const grid = new Map();
  const at = (i, j) => `${i},${j}`;
  cs.forEach((c, k) => {
    const key = at(Math.floor((c.x - x0) / cell), Math.floor((c.y - y0) / cell));
    if (!grid.has(key)) grid.set(key, []);
    grid.get(key).push(k);
  });
  const maxRing = Math.ceil(Math.max(x1 - x0, y1 - y0) / cell) + 1;
  return cs.map((c, k) => {
    const ci = Math.floor((c.x - x0) / cell), cj = Math.floor((c.y - y0) / cell);
    let best = Infinity;
    for (let ring = 0; ring <= maxRing && best > (ring - 1) * cell; ring++)
      for (let i = ci - ring; i <= ci + ring; i++)
        for (let j = cj - ring; j <= cj + ring; j++) {
          if (Math.max(Math.abs(i - ci), Math.abs(j - cj)) !== ring) continue;
          for (const m of grid.get(at(i, j)) ?? []) if (m !== k) best = Math.min(best, Math.hypot(cs[m].x - c.x, cs[m].y - c.y));
        }
    return best;
  });
}

function layout(mesh, d, selection) {
  if (d.local) {
    const hex = d.local.hex;
    if (typeof mesh.localSheetDiagram === 'function') return mesh.localSheetDiagram(d.sheet, [hex], d.local.rings);
    return mesh.sheetDiagramJSON(d.sheet, { local: [hex], rings: d.local.rings });
  }
  return mesh.sheetDiagramJSON(d.sheet);
}

/** One diagram panel: draws once per mesh state; zoom, pan and selection only touch attributes. */
function createPanel(host, actions, spec, onHover) {
  const box = document.createElement('div');
  box.className = 'diagram';
  box.dataset.sheet = spec.sheet;
  box.innerHTML = `<div class="title"><b></b></div><div class="bar"><button data-act="local" title="k rings around the selected hex">local</button>
    <input data-act="rings" type="number" min="1" max="9" value="2" style="width:36px" title="rings" aria-label="rings" />
    <button data-act="fit" title="fit">fit</button><button data-act="svg" title="download SVG">svg</button><button data-act="close" title="close">✕</button></div>`;
  host.appendChild(box);
  const svg = el('svg', { 'data-sheet': spec.sheet }, box);
  const note = Object.assign(document.createElement('div'), { className: 'diagram-note' });
  box.appendChild(note);
  const root = el('g', {}, svg);
  let diagram = null, spacing = 0.1, frame = null, fitW = 2.4, atFit = true, shapedPanel = false;
  let near = []; // per crossing: the distance to its nearest other crossing (diagram units)
  let drawing = root; // the current drawing's group (a fading ghost of the previous one may sit before it)
  let vb = { x: -1.2, y: -1.2, w: 2.4, h: 2.4 };
  let drawnKey = null;

  function pxPerUnit() {
    const r = svg.getBoundingClientRect();
    return Math.min(r.width / vb.w, r.height / vb.h) || 100;
  }
  function applyView() {
    svg.setAttribute('viewBox', `${vb.x} ${vb.y} ${vb.w} ${vb.h}`);
    const s = pxPerUnit();
    const labels = drawing.querySelector('.labels');
    let shown = 0;
    if (labels) {
      labels.setAttribute('font-size', String(LABEL_PX / s));
      // Level of detail, crossing by crossing (as the CLI's SVG): a label shows when it fits before
      // its crossing's nearest neighbour, so sparse parts are labelled while crowded ones are not.
      labels.querySelectorAll('text').forEach((t, k) => {
        const fits = near[k] * s >= Math.max(22, 8 + 6.2 * t.textContent.length);
        t.style.display = fits ? '' : 'none';
        if (fits) shown++;
      });
    }
    for (const c of drawing.querySelectorAll('.crossing')) {
      c.setAttribute('r', String(Math.min(0.32 * spacing, 6 / s)));
      c.setAttribute('stroke-width', String(1.2 / s));
    }
    for (const l of drawing.querySelectorAll('.chord')) l.setAttribute('stroke-width', String((l.classList.contains('sel') ? 5 : 2) / s));
    for (const l of drawing.querySelectorAll('.loop')) l.setAttribute('stroke-width', String(1.5 / s));
    for (const t of drawing.querySelectorAll('.labels text')) {
      placeLabel(t, Number(t.dataset.x), Number(t.dataset.y), s);
    }
    box.dataset.zoom = String(fitW / vb.w);
    box.dataset.labels = shown > 0 ? 'shown' : 'hidden';
  }
  // The drawing's box in the panel's own shape (a long disk fills a wide panel), y flipped.
  function fit() {
    const f = frame ?? { cx: 0, cy: 0, hx: 1.15, hy: 1.15 };
    const r = svg.getBoundingClientRect();
    const aspect = r.width > 0 && r.height > 0 ? r.width / r.height : 1;
    const w = Math.max(2 * f.hx, 2 * f.hy * aspect), h = w / aspect;
    vb = { x: f.cx - w / 2, y: -f.cy - h / 2, w, h };
    fitW = w;
    atFit = true;
    applyView();
  }
  // A zoom by k about the point at client (cx, cy), the panel's aspect kept.
  function zoomAt(cx, cy, k, from = vb) {
    const r = svg.getBoundingClientRect();
    const s = Math.min(r.width / from.w, r.height / from.h) || 100;
    const ux = from.x + (cx - r.left - (r.width - from.w * s) / 2) / s;
    const uy = from.y + (cy - r.top - (r.height - from.h * s) / 2) / s;
    const w = Math.min(8 * fitW, Math.max(fitW / 200, from.w * k)), f = w / from.w;
    vb = { x: ux - (ux - from.x) * f, y: uy - (uy - from.y) * f, w, h: from.h * f };
    atFit = false;
    applyView();
  }
  let motion = null;
  // Draws a layout; `animate`: from the previous drawing of this panel (the same sheet, a step later).
  function draw(d, animate = false) {
    motion?.cancel();
    const old = animate && diagram && drawing !== root ? { places: crossingPlaces(diagram), g: drawing } : null;
    diagram = d;
    root.replaceChildren();
    if (old) root.appendChild(old.g).classList.add('ghost');
    const g = el('g', { transform: 'scale(1,-1)' }, root);
    drawing = g;
    frame = diagramFrame(d);
    if (!shapedPanel) {
      // The first drawing of a long disk gives its panel the drawing's shape (wide, or low on a phone).
      shapedPanel = true;
      const a = frame.hx / frame.hy;
      if (a >= 1.6) {
        if (window.matchMedia('(max-width: 700px)').matches) box.style.height = `${Math.max(170, Math.round(box.clientWidth / a + 90))}px`;
        else {
          const w = Math.min(Math.round(340 * Math.min(a, 2.4)), Math.max(340, (host.parentElement?.clientWidth ?? 800) - 40));
          box.style.width = `${w}px`;
          box.style.height = `${Math.max(220, Math.round(w / a + 110))}px`;
        }
      }
    }
    near = nearest(d.crossings);
    // About the distance between evenly spread crossings (0.55 of the even spacing over what they fill).
    spacing = Math.max(0.004, Math.sqrt(frame.area / Math.max(1, d.crossings.length)) * 0.55);
    if (d.local) el('circle', { cx: 0, cy: 0, r: 1, fill: 'none', stroke: '#666', 'stroke-width': 0.01, 'stroke-dasharray': '0.04 0.03' }, g);
    d.loops.forEach((loop, i) => el('polygon', { points: loop.map((p) => p.join(',')).join(' '), fill: i === 0 ? '#f4f6fa' : 'white', stroke: '#222', class: 'loop' }, g));
    const cells = el('g', { class: 'cells' }, g);
    for (const c of d.cells || []) {
      const r = el('rect', { x: c.x - spacing * 0.18, y: c.y - spacing * 0.18, width: spacing * 0.36, height: spacing * 0.36, fill: 'transparent', class: 'cell', 'data-edge': `h${c.edge[0]}e${c.edge[1]}` }, cells);
      el('title', {}, r).textContent = `edge h${c.edge[0]}e${c.edge[1]}`;
    }
    const chords = d.chords.map((c) => {
      const line = el('polyline', { points: c.points.map((p) => p.join(',')).join(' '), fill: 'none', stroke: chordColor(c.id), class: 'chord', 'data-chord': c.id }, g);
      el('title', {}, line).textContent = `chord ${c.id} (with sheet ${c.otherSheet})${c.closed ? ', closed' : ''}`;
      return line;
    });
    for (const b of d.boundary) {
      const r = el('rect', { x: b.x - spacing * 0.12, y: b.y - spacing * 0.12, width: spacing * 0.24, height: spacing * 0.24, fill: '#222', class: 'bquad', 'data-quad': `h${b.hex}f${b.face}` }, g);
      el('title', {}, r).textContent = `boundary quad h${b.hex}f${b.face}`;
    }
    const crossings = el('g', {}, g);
    const dots = d.crossings.map((c) => {
      const dot = el('circle', { cx: c.x, cy: c.y, r: 0.02, fill: c.outside ? '#fc6' : 'white', stroke: '#111', class: 'crossing', 'data-hex': c.hex, 'data-key': crossingKey(c) }, crossings);
      el('title', {}, dot).textContent = `hex h${c.hex} (chords ${c.chords.join(', ')})`;
      return dot;
    });
    const labels = el('g', { class: 'labels', transform: 'scale(1,-1)' }, g);
    const texts = d.crossings.map((c) => {
      const t = el('text', { 'data-x': c.x, 'data-y': c.y, 'data-key': crossingKey(c) }, labels);
      t.dataset.room = String(frame.right - c.x);
      t.textContent = String(c.hex);
      return t;
    });
    box.querySelector('.title b').textContent = `sheet ${d.sheet} · ${d.topology}${d.method !== d.topology ? ` · ${d.method}` : ''} · ${d.crossings.length} crossings`;
    note.textContent = d.note || '';
    fit();
    if (old) motion = animateCrossings(old, d, dots, texts, chords);
  }

  // Moves the crossings from the previous drawing's places (labels follow at the zoom's offset).
  function animateCrossings(old, d, dots, texts, chords) {
    const items = d.crossings.map((c, k) => ({
      key: crossingKey(c), x: c.x, y: c.y, els: [dots[k], texts[k]],
      place(x, y) {
        const s = pxPerUnit();
        dots[k].setAttribute('cx', x);
        dots[k].setAttribute('cy', y);
        placeLabel(texts[k], x, y, s);
      },
    }));
    return animateDiagram({ old: old.places, ghost: old.g, items, fadeIn: chords });
  }

  // ---- zoom and pan ----
  svg.addEventListener('wheel', (e) => {
    e.preventDefault();
    zoomAt(e.clientX, e.clientY, Math.exp(Math.sign(e.deltaY) * 0.18));
  }, { passive: false });
  // One pointer drags (pans); two pinch (zoom about their midpoint, which the fingers also move).
  let drag = null, pinch = null;
  const pointers = new Map();
  const pair = () => [...pointers.values()].slice(0, 2);
  svg.addEventListener('pointerdown', (e) => {
    pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    try {
      svg.setPointerCapture(e.pointerId);
    } catch {}
    if (pointers.size === 1) {
      drag = { x: e.clientX, y: e.clientY, vx: vb.x, vy: vb.y, moved: false };
      return;
    }
    const [a, b] = pair();
    pinch = { d: Math.max(1, Math.hypot(a.x - b.x, a.y - b.y)), mx: (a.x + b.x) / 2, my: (a.y + b.y) / 2, vb: { ...vb } };
    if (drag) drag.moved = true; // a pinch is not a tap
  });
  svg.addEventListener('pointermove', (e) => {
    if (pointers.has(e.pointerId)) pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
    if (pinch && pointers.size >= 2) {
      const [a, b] = pair();
      const d = Math.max(1, Math.hypot(a.x - b.x, a.y - b.y));
      zoomAt(pinch.mx, pinch.my, pinch.d / d, pinch.vb);
      const s = pxPerUnit();
      vb.x -= ((a.x + b.x) / 2 - pinch.mx) / s;
      vb.y -= ((a.y + b.y) / 2 - pinch.my) / s;
      applyView();
      return;
    }
    if (!drag) return;
    const s = pxPerUnit();
    if (Math.hypot(e.clientX - drag.x, e.clientY - drag.y) > 3) drag.moved = true;
    vb.x = drag.vx - (e.clientX - drag.x) / s;
    vb.y = drag.vy - (e.clientY - drag.y) / s;
    if (drag.moved) {
      atFit = false;
      applyView();
    }
  });
  const lift = (e) => {
    pointers.delete(e.pointerId);
    if (pointers.size < 2) pinch = null;
  };
  svg.addEventListener('pointercancel', (e) => {
    lift(e);
    if (pointers.size === 0) drag = null;
  });
  svg.addEventListener('pointerup', (e) => {
    lift(e);
    if (pointers.size > 0) return; // the other finger of a pinch is still down
    const d = drag;
    drag = null;
    if (d && d.moved) return;
    const target = document.elementFromPoint(e.clientX, e.clientY);
    const t = target?.closest?.('[data-hex], [data-chord], [data-edge], [data-quad]');
    if (!t) return;
    if (t.dataset.hex) actions.select({ kind: 'hex', hex: Number(t.dataset.hex) });
    else if (t.dataset.chord) actions.select({ kind: 'chord', id: Number(t.dataset.chord) });
    else if (t.dataset.edge) {
      const m = /^h(\d+)e(\d+)$/.exec(t.dataset.edge);
      actions.select({ kind: 'edge', hex: +m[1], edge: +m[2] });
    } else if (t.dataset.quad) {
      const m = /^h(\d+)f(\d+)$/.exec(t.dataset.quad);
      actions.select({ kind: 'quad', hex: +m[1], face: +m[2] });
    }
  });
  // The hex of the crossing under the pointer is shown in 3D too.
  svg.addEventListener('pointerover', (e) => {
    const c = e.target.closest?.('.crossing');
    if (c) onHover({ kind: 'hex', hex: Number(c.dataset.hex) });
  });
  svg.addEventListener('pointerout', (e) => e.target.closest?.('.crossing') && onHover(null));
  // A resized panel keeps its zoom, or fits again when the user had not zoomed or panned.
  new ResizeObserver(() => diagram && (atFit ? fit() : applyView())).observe(svg);

  box.querySelector('.bar').addEventListener('click', (e) => {
    const act = e.target.dataset.act;
    const s = window.hexdual.store.get();
    if (act === 'close') actions.closeDiagram(spec.sheet);
    if (act === 'fit') fit();
    if (act === 'svg') downloadSvg();
    if (act === 'local') {
      const hex = s.selection && 'hex' in s.selection ? s.selection.hex : null;
      if (spec.local) actions.toggleDiagram(spec.sheet, null), actions.toggleDiagram(spec.sheet);
      else if (hex !== null) actions.toggleDiagram(spec.sheet, { hex, rings: Number(box.querySelector('[data-act=rings]').value) || 2 });
      else actions.set({ error: 'local diagram: select a hex, quad or edge on the sheet first' });
    }
  });

  function downloadSvg() {
    const copy = svg.cloneNode(true);
    copy.setAttribute('xmlns', NS);
    const r = svg.getBoundingClientRect();
    copy.setAttribute('width', String(Math.round(r.width)));
    copy.setAttribute('height', String(Math.round(r.height)));
    const blob = new Blob([new XMLSerializer().serializeToString(copy)], { type: 'image/svg+xml' });
    const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(blob), download: `sheet-${spec.sheet}.svg` });
    document.body.appendChild(a); // a detached link does not download in every browser
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }

  function mark(selection) {
    for (const x of drawing.querySelectorAll('.sel')) x.classList.remove('sel');
    if (!selection) return applyView();
    const id = formatSelection(selection);
    if (selection.kind === 'chord') drawing.querySelector(`[data-chord="${selection.id}"]`)?.classList.add('sel');
    if ('hex' in selection) drawing.querySelectorAll(`.crossing[data-hex="${selection.hex}"]`).forEach((c) => c.classList.add('sel'));
    if (selection.kind === 'edge') drawing.querySelector(`[data-edge="${id}"]`)?.classList.add('sel');
    if (selection.kind === 'quad') drawing.querySelector(`[data-quad="${id}"]`)?.classList.add('sel');
    applyView();
  }

  return {
    box,
    spec,
    update(s, specNow) {
      const sameSpec = JSON.stringify(spec) === JSON.stringify(specNow);
      spec = specNow;
      const key = `${s.meshKey}|${JSON.stringify(spec)}`;
      if (key !== drawnKey) {
        // A step (or a move in time) on the same start mesh, the same sheet drawn the same way: animated.
        const animate = sameSpec && drawnKey !== null && drawnKey.split(':')[0] === s.meshKey.split(':')[0];
        drawnKey = key;
        try {
          draw(layout(s.mesh, spec, s.selection), animate);
        } catch (e) {
          root.replaceChildren();
          drawing = root;
          box.querySelector('.title b').textContent = `sheet ${spec.sheet}`;
          note.textContent = e.message;
        }
        box.querySelector('[data-act=local]').classList.toggle('on', !!spec.local);
      }
      mark(s.selection);
    },
    get diagram() {
      return diagram;
    },
    get animating() {
      return !!motion?.running;
    },
  };
}

/** `onHover(pick | null)`: a crossing under the pointer, to show its hex in 3D (as the tutorials do). */
export function createDiagrams(host, actions, { onHover = () => {} } = {}) {
  const panels = new Map();
  const style = document.createElement('style');
  style.textContent = `.diagram .sel.crossing { fill: #ff7a00; } .diagram .sel.cell { fill: rgba(255,122,0,0.6); }
    .diagram .sel.bquad { fill: #ff7a00; } .diagram .chord.sel { filter: drop-shadow(0 0 1px #000); }
    .diagram .labels text { pointer-events: none; fill: #111; } .diagram .ghost { pointer-events: none; } .diagram [data-act=local].on { background: #223; color: #fff; }`;
  document.head.appendChild(style);
  return {
    update(s) {
      if (!s.mesh) return;
      const want = new Map(s.diagrams.map((d) => [d.sheet, d]));
      for (const [sheet, p] of panels) if (!want.has(sheet)) (p.box.remove(), panels.delete(sheet));
      for (const [sheet, d] of want) {
        if (!panels.has(sheet)) panels.set(sheet, createPanel(host, actions, d, onHover));
        panels.get(sheet).update(s, d);
      }
    },
    panels,
  };
}
