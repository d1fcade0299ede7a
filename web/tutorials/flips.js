// Page 7: the flips of the 4-cube boundary and their stored atomic decompositions, stepped through.
import { flips } from '../../wasm/index.js';
import { startPage, live } from './page.js';
import { createFigure, meshAfter } from './figure.js';

const FOURCUBE = { kind: 'fourcube', dims: [] };
const BEFORE = '#7aa6ff';

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

startPage(() => {
  const all = flips();
  const m = meshAfter(FOURCUBE, []);
  live('cubes', m.counts.hexes);
  live('fc-vertices', m.counts.vertices);
  live('fc-quads', m.counts.quads);
  m.delete();
  const forward = all.filter((f) => /^\d/.test(f.name) && Number(f.name[0]) <= Number(f.name.split('-')[1]?.[0] ?? 9));
  live('flip-names', forward.map((f) => f.name).join(', '));
  live('open-flips', all.filter((f) => !f.steps).map((f) => f.name).join(', ') || 'none');
  fillTable(all);

  const select = document.getElementById('flip-name');
  for (const f of all.filter((x) => x.steps)) select.append(new Option(`${f.name} (${f.steps.length} steps)`, f.name));
  let fig = null;
  const show = (name) => {
    const f = all.find((x) => x.name === name);
    fig?.destroy();
    live('flip-summary', `${f.description || ''}`);
    fig = createFigure(document.getElementById('fig-flip'), {
      title: `the ${f.name} flip`,
      mesh: FOURCUBE,
      steps: f.steps,
      emphasis: (fg, id) => (f.before.includes(id) ? BEFORE : null),
      sheet: (fg) => fg.mesh.sheets.find((s) => fg.mesh.sheetHexes(s.id).some((h) => f.before.includes(h)))?.id,
      sheetChips: true,
      sheetIn3d: false,
      caption: `The closed boundary of the 4-cube; the ${f.name} flip's before side is cube${f.before.length === 1 ? '' : 's'} ${f.before.join(', ')}.`,
    });
  };
  select.addEventListener('change', () => show(select.value));
  show(select.value);
});
