// Draws the primal before/after pictures of docs/operations.md as SVG, from the package's own render
// buffers: each hex shrunk toward its dual point (so a pillow's two hexes or a blind chord's pair
// draw apart), the hexes the step names or creates opaque, their face neighbours faint around them.
// Usage (after the wasm build): node docs/primal-figures.mjs [outdir]   (default docs/images)
import { mkdirSync, writeFileSync } from 'node:fs';
import { init, Mesh } from '../wasm/index.node.js';

const OUT = process.argv[2] ?? new URL('./images/', import.meta.url).pathname;
const SHRINK = 0.2;
const EXPLODE = 0.7;  // each hex moves away from the step's centre by this fraction of its distance (default)
const COLOURS = { step: '#5b8fd6', created: '#f28e2b', removed: '#d62728', context: '#c8c8c8' };

// The scenes: a mesh, one step, and a view direction (azimuth, elevation in degrees).
const SCENES = [
  { name: 'pillow', mesh: () => Mesh.grid(3, 3, 3), step: 'pillow h13f5', view: [35, 28] },
  { name: 'chordpush', mesh: () => Mesh.grid(5, 5, 5), step: 'chordpush h62e11 h62f1 h67f1', view: [35, 28] },
  { name: 'hexpush', mesh: () => Mesh.grid(5, 5, 5), step: 'hexpush h62f5', view: [30, 18], explode: 1.3 },
  { name: 'ringcollapse', mesh: () => Mesh.ring(8, 3, 3), step: 'ringcollapse h25e4', view: [20, 55] },
  { name: 'facecollapse', mesh: () => Mesh.grid(4, 4, 4), step: 'facecollapse h21e11 h21f1 h25f1', view: [35, 28] },
];

/** Hex ids a step names: every `hN` in its text, and the hex across each named quad `hNfK`. */
function namedHexes(mesh, step) {
  const named = [...step.matchAll(/h(\d+)/g)].map((m) => Number(m[1]));
  for (const m of step.matchAll(/h(\d+)f(\d)/g)) named.push(hexAcross(mesh, Number(m[1]), Number(m[2])));
  return [...new Set(named)].filter((h) => h >= 0);
}

/** The hex whose centre is nearest to hex h's centre mirrored through the centre of its face f. */
function hexAcross(mesh, h, f) {
  const c = mesh.hexCenters(), d = mesh.dualPoints(), rb = mesh.renderBuffers({ shrink: 0 });
  const face = rb.triangleHex.indexOf(h) / 2 + f;  // a hex's six faces are consecutive, in order
  const target = [0, 1, 2].map((k) => {
    let mean = 0;
    for (let q = 0; q < 4; ++q) mean += rb.positions[3 * (4 * face + q) + k] / 4;
    return c[3 * h + k] + 2 * (mean - d[3 * h + k]);
  });
  let best = -1, bestD = Infinity;
  for (let g = 0; 3 * g < c.length; ++g) {
    const dist = Math.hypot(c[3 * g] - target[0], c[3 * g + 1] - target[1], c[3 * g + 2] - target[2]);
    if (g !== h && dist < bestD) [best, bestD] = [g, dist];
  }
  return bestD < 0.5 ? best : -1;
}

/** Face neighbours of the focus hexes, by geometry: for each focus hex, the hexes whose centre is
 *  within 1.3 times its nearest neighbour's distance (in a grid: its six face neighbours). */
function neighbours(mesh, focus) {
  const c = mesh.hexCenters(), n = c.length / 3;
  const dist = (g, h) => Math.hypot(c[3 * g] - c[3 * h], c[3 * g + 1] - c[3 * h + 1], c[3 * g + 2] - c[3 * h + 2]);
  const near = new Set();
  for (const f of focus) {
    const others = [...Array(n).keys()].filter((h) => h !== f && Number.isFinite(c[3 * h]));
    const nearest = Math.min(...others.map((h) => dist(f, h)));
    for (const h of others) if (dist(f, h) <= 1.3 * nearest && !focus.includes(h)) near.add(h);
  }
  return near;
}

/** Quads of the shown hexes as polygons in view space, with the colour of their role. */
function quads(mesh, roleOf, [azimuth, elevation], centre, explode) {
  const rb = mesh.renderBuffers({ shrink: SHRINK }), dp = mesh.dualPoints();
  const a = (azimuth * Math.PI) / 180, e = (elevation * Math.PI) / 180;
  const project = (i, h) => {
    const [x, y, z] = [0, 1, 2].map((k) => rb.positions[3 * i + k] + explode * (dp[3 * h + k] - centre[k]));
    const u = x * Math.cos(a) - y * Math.sin(a);
    const w = x * Math.sin(a) + y * Math.cos(a);
    return { u, v: z * Math.cos(e) - w * Math.sin(e), depth: w * Math.cos(e) + z * Math.sin(e) };
  };
  const out = [];
  for (let face = 0; 2 * face < rb.triangleHex.length; ++face) {
    const h = rb.triangleHex[2 * face], role = roleOf(h);
    if (!role) continue;
    const p = [0, 1, 2, 3].map((k) => project(4 * face + k, h));
    out.push({ role, p, depth: p.reduce((s, q) => s + q.depth, 0) / 4 });
  }
  return out;
}

/** One panel: quads drawn back to front, faint context first so the focus stays on top of it. */
function panel(polys, box, dx) {
  const { u0, v0, scale, size } = box;
  const xy = (q) => `${((q.u - u0) * scale + 10 + dx).toFixed(1)},${(size - ((q.v - v0) * scale + 10)).toFixed(1)}`;
  const order = (r) => (r === 'context' ? 0 : 1);
  polys.sort((x, y) => order(x.role) - order(y.role) || x.depth - y.depth);
  return polys.map(({ role, p }) => {
    const faint = role === 'context';
    return `<polygon points="${p.map(xy).join(' ')}" fill="${COLOURS[role]}" fill-opacity="${faint ? 0.18 : 0.92}" ` +
      `stroke="${faint ? '#9a9a9a' : '#222'}" stroke-width="${faint ? 0.6 : 1}" stroke-linejoin="round"/>`;
  }).join('\n');
}

/** The mean dual point of some hexes. */
function centreOf(mesh, hexes) {
  const dp = mesh.dualPoints();
  return [0, 1, 2].map((k) => hexes.reduce((s, h) => s + dp[3 * h + k], 0) / hexes.length);
}

/** Before | arrow | after, with a caption under each and a legend of the colours. */
function figure(before, after, box, step, report) {
  const { size } = box, gap = 60, w = 2 * size + gap, h = size + 76;
  const text = (x, y, t, anchor = 'middle') =>
    `<text x="${x}" y="${y}" text-anchor="${anchor}" font-family="sans-serif" font-size="14" fill="#222">${t}</text>`;
  const d = report.delta;
  const legend = [['step', 'named by the step'], ['created', 'created'], ['removed', 'removed'], ['context', 'neighbours']]
    .map(([role, label], i) => `<rect x="${10 + i * 165}" y="${h - 18}" width="12" height="12" fill="${COLOURS[role]}" ` +
      `stroke="#222" stroke-width="0.5"/>` + text(28 + i * 165, h - 7, label, 'start'));
  return `<svg xmlns="http://www.w3.org/2000/svg" width="${w}" height="${h}" viewBox="0 0 ${w} ${h}">` +
    `<rect width="100%" height="100%" fill="#fff"/>\n${panel(before, box, 0)}\n${panel(after, box, size + gap)}\n` +
    `<path d="M ${size + 12} ${size / 2} h ${gap - 24} m -8 -6 l 8 6 l -8 6" stroke="#444" stroke-width="2" fill="none"/>\n` +
    text(size / 2, size + 16, 'before') +
    text(size + gap + size / 2, size + 16, `after ${step}`) +
    text(size + gap + size / 2, size + 34, `Δ(V,E,F,H) = (${d.V}, ${d.E}, ${d.F}, ${d.H})`) +
    `\n${legend.join('\n')}\n</svg>\n`;
}

/** The same frame for before and after, so the two pictures line up. */
function frame(all, size) {
  const us = all.flatMap((q) => q.p.map((p) => p.u)), vs = all.flatMap((q) => q.p.map((p) => p.v));
  const u0 = Math.min(...us), v0 = Math.min(...vs);
  const span = Math.max(Math.max(...us) - u0, Math.max(...vs) - v0);
  return { u0, v0, scale: (size - 20) / span, size };
}

function scene({ name, mesh: make, step, view, explode = EXPLODE }) {
  const mesh = make();
  const named = namedHexes(mesh, step);
  const centre = centreOf(mesh, named);
  const report = mesh.apply(step);
  const created = new Set(report.created.hexes), removed = new Set(report.removed.hexes);
  mesh.undo();
  const context = neighbours(mesh, [...new Set([...named, ...removed])]);
  const role = (h) =>
    created.has(h) ? 'created' : removed.has(h) ? 'removed' : named.includes(h) ? 'step' : context.has(h) ? 'context' : null;
  const before = quads(mesh, role, view, centre, explode);
  mesh.redo();
  const after = quads(mesh, role, view, centre, explode);
  const box = frame([...before, ...after], 300);
  writeFileSync(`${OUT}/op-${name}-primal.svg`, figure(before, after, box, step, report));
  mesh.delete();
  return `${name}: ${step} → created ${report.created.hexes.length}, removed ${report.removed.hexes.length}`;
}

await init();
mkdirSync(OUT, { recursive: true });
for (const s of SCENES) console.log(scene(s));
