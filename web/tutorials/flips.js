// Page 7: the flips of the 4-cube boundary and their stored atomic decompositions, stepped through
// in an exploded view of the 4-cube (fourCube.js). Every count and bound on the page is read from
// the stored records (decompositions()) or computed by the engine.
import { flips } from '../../wasm/index.js';
import { startPage, live, record, chordOnlyBound } from './page.js';
import { createFigure, meshAfter } from './figure.js';
import { explodedLayout, flipColors, cubeLabels } from './fourCube.js';

const FOURCUBE = { kind: 'fourcube', dims: [] };
const TCP_MESH = 'grid:3x3x3';

function fillTable(all) {
  const body = document.querySelector('#flip-table tbody');
  for (const f of all) {
    const tr = document.createElement('tr');
    const cells = [f.name, f.inverse, f.geometric ? 'yes' : 'no', `${f.before.length} cube${f.before.length === 1 ? '' : 's'}`];
    for (const text of cells) tr.append(Object.assign(document.createElement('td'), { textContent: text }));
    const steps = document.createElement('td');
    if (f.steps) steps.append(Object.assign(document.createElement('code'), { textContent: f.steps.join('; ') }));
    else steps.textContent = 'none found';
    tr.append(steps);
    body.append(tr);
  }
}

const opNames = (steps) => steps.map((s) => s.split(' ')[0]).map((op) => op.replace(/^(\w+?)(push|pull|collapse|split)$/, '$1 $2')).join(', ');
const cubes = (ids) => ids.map((h) => `cube ${h}`).join(', ');

// The largest region (hexes that are not host cubes) along a flip's stored steps in the 4-cube.
function largestRegion(f) {
  const m = meshAfter(FOURCUBE, []);
  const host = 8 - f.before.length;
  let most = m.counts.hexes - host;
  for (const s of f.steps) {
    m.apply(s);
    most = Math.max(most, m.counts.hexes - host);
  }
  m.delete();
  return most;
}

function openQuestions(all) {
  const v44 = record('4-4v');
  live('v44-steps', v44.steps.length);
  live('v44-ops', opNames(v44.steps));
  live('v44-shorter', v44.depthSearched - 1);
  live('v44-states', v44.states.toLocaleString('en'));
  live('v44-region', largestRegion(all.find((f) => f.name === '4-4v')));
  const tcp = record('tripleChordPush');
  live('tcp-steps', tcp.steps.length);
  live('tcp-ops', opNames(tcp.steps));
  live('tcp-shorter', tcp.depthSearched - 1);
  live('tcp-states', tcp.states.toLocaleString('en'));
  const steps = ['v1', ...tcp.steps].join(';').replace(/ /g, '%20');
  document.getElementById('tcp-explorer').href = `../index.html#mesh=${TCP_MESH}&steps=${steps}&at=0&slice=z:0.4`;
  // Δ(hexes) of a chord push and a hex push, from the engine.
  const m = meshAfter({ kind: 'grid', dims: [3, 3, 3] }, []);
  const push = m.apply('chordpush h13e3 h13f3 h16f5').delta.H;
  m.undo();
  const hexPush = m.apply('hexpush h13f5').delta.H;
  m.delete();
  live('chord-only-bound', chordOnlyBound({ push, hexPush }).bound);
}

startPage(() => {
  const all = flips();
  const m = meshAfter(FOURCUBE, []);
  live('cubes', m.counts.hexes);
  live('fc-vertices', m.counts.vertices);
  live('fc-quads', m.counts.quads);
  const layout = explodedLayout(m);
  live('outer-cube', [...layout(m).outer].join(', '));
  m.delete();
  const forward = all.filter((f) => /^\d/.test(f.name) && Number(f.name[0]) <= Number(f.name.split('-')[1]?.[0] ?? 9));
  live('flip-names', forward.map((f) => f.name).join(', '));
  live('open-flips', all.filter((f) => !f.steps).map((f) => f.name).join(', ') || 'none');
  fillTable(all);
  openQuestions(all);

  const select = document.getElementById('flip-name');
  for (const f of all.filter((x) => x.steps)) select.append(new Option(`${f.name} (${f.steps.length} step${f.steps.length === 1 ? '' : 's'})`, f.name));
  let fig = null;
  const show = (name) => {
    const f = all.find((x) => x.name === name);
    fig?.destroy();
    live('flip-summary', `${f.description || ''}`);
    live('before-cubes', cubes(f.before));
    live('after-cubes', cubes([...Array(8).keys()].filter((h) => !f.before.includes(h))));
    const root = document.getElementById('fig-flip');
    root.classList.add('wide');
    fig = createFigure(root, {
      title: `the ${f.name} flip in the 4-cube`,
      mesh: FOURCUBE,
      steps: f.steps,
      layout,
      shrink: 0.3,
      emphasis: flipColors(f.before),
      hexLabels: cubeLabels(f.before),
      sheet: (fg) => fg.mesh.sheets.find((s) => [...fg.mesh.sheetHexes(s.id)].some((h) => f.before.includes(h)))?.id,
      sheetChips: true,
      sheetIn3d: false,
      hint: 'Drag to turn the 4-cube; hover a cube to see its sheets.',
      caption: `The closed boundary of the 4-cube, exploded; the ${f.name} flip replaces cube${f.before.length === 1 ? '' : 's'} ${f.before.join(', ')} (blue) by new hexes (green) shaped like the other side (orange).`,
    });
  };
  select.addEventListener('change', () => show(select.value));
  show(select.value);
});
