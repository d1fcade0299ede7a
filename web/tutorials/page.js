// Shared by every tutorial page: loads the engine, adds the page navigation, fills live numbers,
// and reports readiness (window.tutorial.ready) for the browser tests.
import { init, decompositions } from '../../wasm/index.js';
import wasmUrl from '../../wasm/dist/hexdual.wasm?url';

export const PAGES = [
  ['dual.html', 'A hex mesh and its dual'],
  ['diagrams.html', 'Reading sheet diagrams'],
  ['simple.html', 'Why the dual is a simple arrangement'],
  ['pillow.html', 'The minimal pillow'],
  ['push.html', 'Chord push and hex push'],
  ['collapse.html', 'Traditional pillow, ring and face collapse'],
  ['flips.html', 'Flips'],
  ['puzzles.html', 'Puzzles'],
];

function nav() {
  const here = location.pathname.split('/').pop() || 'index.html';
  const k = PAGES.findIndex(([file]) => file === here);
  const bar = document.createElement('nav');
  bar.className = 'pager';
  bar.setAttribute('aria-label', 'tutorial pages');
  const link = (href, text, rel) => Object.assign(document.createElement('a'), { href, textContent: text, rel });
  bar.append(link('index.html', 'All tutorials', 'index'));
  if (k > 0) bar.append(link(PAGES[k - 1][0], `← ${PAGES[k - 1][1]}`, 'prev'));
  if (k >= 0 && k < PAGES.length - 1) bar.append(link(PAGES[k + 1][0], `${PAGES[k + 1][1]} →`, 'next'));
  bar.append(link('../index.html', 'Explorer', ''));
  document.querySelector('main').append(bar);
}

let records = null;
/** The stored decomposition record of a problem (core/flips/decompositions.txt via the package). */
export function record(problem) {
  records ??= decompositions();
  const r = records.find((x) => x.problem === problem);
  if (!r) throw new Error(`no stored decomposition record for ${problem}`);
  return r;
}

/**
 * What the chord-only search of the hex push (record 2-6/chord-only) shows, with the parity
 * argument of docs/flips.md from the engine's own Δ(hexes): a chord push adds `push` hexes, a pull
 * removes as many, the hex push adds `hexPush`, so every chord-only sequence doing the hex push
 * has the parity of hexPush / push; when the search's depth has the other parity, one more is ruled out.
 */
export function chordOnlyBound({ push, hexPush }) {
  const r = record('2-6/chord-only');
  const parity = Math.abs(hexPush / push) % 2;
  const searched = r.depthSearched;
  return { searched, states: r.states, parity, bound: (searched + 1) % 2 !== parity ? searched + 1 : searched };
}

/** Sets the text of every element with data-live=NAME. */
export function live(name, value) {
  for (const e of document.querySelectorAll(`[data-live="${name}"]`)) e.textContent = String(value);
}

export function signed(n) {
  return n > 0 ? `+${n}` : n < 0 ? `−${-n}` : '0';
}

/** Δ(V,E,F,H) of a figure as "(+4, +8, +6, +2)". */
export function deltaText(d) {
  return `(${[d.vertices, d.edges, d.quads, d.hexes].map(signed).join(', ')})`;
}

export async function startPage(build) {
  window.tutorial ||= { figures: [] };
  const t0 = performance.now();
  nav();
  await init({ locateFile: (p) => (p.endsWith('.wasm') ? wasmUrl : p) });
  const t1 = performance.now();
  try {
    await build();
    // Let the figures in sight make and draw their 3D views before calling the page ready.
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => setTimeout(r, 0))));
  } finally {
    const t2 = performance.now();
    // Where the time to interactive goes (printed by the browser tests).
    window.tutorial.timings = { engineMs: Math.round(t1 - t0), pageMs: Math.round(t2 - t1), sinceNavigationMs: Math.round(t2) };
    window.tutorial.ready = true;
  }
}
