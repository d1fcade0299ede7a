// Page 8: puzzles played in the figure. A pick in 3D (quad, edge or hex) or on the sheet diagram
// (a crossing = a hex) lists the operations the engine says apply there (candidates.js); pointing
// at one previews it in the figure, a click applies it. The goal is checked by the engine after
// every step; the score compares the steps used with the shortest known (puzzles.js). Progress is
// in the URL and localStorage (progress.js); typing steps stays possible.
import { flips } from '../../wasm/index.js';
import { startPage, record } from './page.js';
import { createFigure, meshAfter } from './figure.js';
import { PUZZLES, preparePuzzle, checkPuzzle, stars, placeOf } from './puzzles.js';
import { createCandidates, stepsAt } from './candidates.js';
import { createProgress, parsePuzzleHash, puzzleHash } from './progress.js';
import { stepText, effectText, pickText } from './stepText.js';
import { revealInStrip } from '../scrollStrip.js';
import { explodedLayout, flipColors, cubeLabels } from './fourCube.js';

const eng = { build: meshAfter, flips, record, stepsAt };
const $ = (id) => document.getElementById(id);
const BLUE = '#4d8ef0';
const HOVER = '#1f6feb', PICK = '#ff7a00', NEXT = '#2f9e44';
const progress = createProgress();
const S = { p: null, prep: null, steps: [], reports: [], pick: null, hover: null, hints: 0, next: null, fig: null, refHashes: [] };

const parseTyped = (text) => text.split(/[;\n]/).map((s) => s.trim().replace(/\s+/g, ' ')).filter((s) => s && s !== 'v1');
const pickMode = () => document.querySelector('input[name=pick]:checked').value;
const startOps = () => S.p.pre;
const allOps = (steps = S.steps) => [...S.p.pre, ...steps];

function stages() {
  return [{ ops: startOps(), label: 'start' }, ...S.steps.map((s, k) => ({ ops: allOps(S.steps.slice(0, k + 1)), label: s }))];
}

// Colours: a 4-cube flip in its two sides, a grid flip's before side or the focus in blue.
function emphasisFor(p) {
  if (p.mesh.kind === 'fourcube') return flipColors(p.flip.before);
  const blue = new Set(p.flip ? p.flip.before : p.focus || []);
  return (fig, id) => (blue.has(id) && !fig.isCreated(id) ? BLUE : null);
}

function labelsFor(p) {
  if (p.mesh.kind === 'fourcube') return cubeLabels(p.flip.before);
  const few = new Set(p.focus || []);
  return (fig) => fig.liveIds().filter((h) => !p.focus || few.has(h) || fig.isCreated(h)).map((h) => ({ hex: h, text: String(h), cls: fig.isCreated(h) ? 'created' : '' }));
}

// The sheet the diagram shows: one the last step created or changed, else the first.
function sheetFor(fig) {
  const r = S.reports[fig.stage - 1];
  const ids = fig.mesh.sheets.map((s) => s.id);
  const want = r ? [...r.changedSheets.created, ...r.changedSheets.changed] : [];
  return want.find((id) => ids.includes(id)) ?? ids[0];
}

function makeFigure(p) {
  const root = $('fig-puzzle');
  root.before($('candidates')); // keep it while the old figure goes
  S.fig?.destroy();
  root.className = '';
  if (p.mesh.kind === 'fourcube') root.classList.add('wide');
  const start = meshAfter(p.mesh, []);
  const layout = explodedLayout(start, p.mesh.kind === 'fourcube' ? {} : { spread: 0.45 });
  start.delete();
  S.fig = createFigure(root, {
    title: `puzzle: ${p.title}`,
    mesh: p.mesh,
    stages: stages(),
    startAfter: true,
    layout,
    shrink: 0.3,
    emphasis: emphasisFor(p),
    hexLabels: labelsFor(p),
    sheetIn3d: false,
    sheetChips: true,
    sheet: sheetFor,
    pickMode,
    sideTop: $('candidates'),
    hint: 'Pick a quad, an edge or a hex; hover to see what is under the pointer.',
    onPick: (pick) => choose(pick),
    onHover: (pick) => hover(pick),
  });
}

function drawMarks() {
  const items = [];
  if (S.next) items.push([S.next, NEXT, 0.9]);
  if (S.hover) items.push([S.hover, HOVER, 0.45]);
  if (S.pick) items.push([S.pick, PICK, 0.9]);
  S.fig.setMarks(items);
}

function hover(pick) {
  S.hover = pick && pick.kind !== 'hex' ? pick : null;
  $('fig-puzzle').querySelector('.status').textContent = pick ? `under the pointer: ${pickText(pick)}` : '';
  drawMarks();
}

const candidates = createCandidates($('candidates'), {
  onPreview: (step) => S.fig.preview(step ? [...S.fig.stages[S.fig.stage].ops, step] : null),
  onApply: (step) => apply(step),
});

// A pick lists what applies there in the shown stage (a preview, if one is on, ends first).
function choose(pick) {
  S.fig.preview(null);
  S.pick = pick;
  S.lastCandidates = candidates.show(S.fig.mesh, pick);
  drawMarks();
}

/**
 * Applies a step at the shown stage (later steps, if any were stepped back over, are dropped);
 * `quiet`: after the last step (loading a log), without redrawing.
 */
function apply(step, quiet = false) {
  const keep = S.steps.slice(0, quiet ? S.steps.length : S.fig.stage);
  const m = meshAfter(S.p.mesh, allOps(keep));
  try {
    const report = m.apply(step);
    S.steps = [...keep, step];
    S.reports = [...S.reports.slice(0, keep.length), report];
  } catch (e) {
    S.error = `${step}: ${e.message}`;
    $('puzzle-check').textContent = S.error;
    return false;
  } finally {
    m.delete();
  }
  S.next = null;
  if (!quiet) refresh();
  return true;
}

// The steps in play changed: figure, candidates at the pick, goal, log, score, URL and storage.
function refresh(animate = true) {
  S.fig.setStages(stages(), { animate });
  const alive = S.pick && S.fig.liveIds().includes(S.pick.hex);
  if (!alive) S.pick = null;
  choose(S.pick);
  const verdict = checkPuzzle(S.p, S.prep, S.steps, eng);
  const check = $('puzzle-check');
  check.textContent = verdict.message;
  check.className = `check ${verdict.ok ? 'check-ok' : ''}`;
  if (verdict.ok) progress.solve(S.p.id, S.steps.length);
  showScore(verdict.ok);
  showLog();
  $('puzzle').dataset.solved = String(verdict.ok);
  $('puzzle').dataset.steps = String(S.steps.length);
  progress.play(S.p.id, S.steps);
  const hash = puzzleHash(S.p.id, S.steps);
  if (location.hash !== hash) history.replaceState(null, '', hash);
  $('puzzle-share').href = hash;
  listPuzzles();
}

function showScore(ok) {
  const best = S.prep.best;
  const el = $('puzzle-score');
  const n = S.steps.length;
  const known = `Shortest known: ${best.steps} step${best.steps === 1 ? '' : 's'} (${best.source}).`;
  if (!ok) return void (el.textContent = `Steps so far: ${n}. ${known}`);
  const k = stars(n, best.steps);
  el.innerHTML = '';
  el.append(`Solved in ${n} step${n === 1 ? '' : 's'}. ${known} `);
  el.append(Object.assign(document.createElement('span'), { className: 'stars', textContent: '★'.repeat(k) + '☆'.repeat(3 - k), title: `${k} of 3` }));
  const i = PUZZLES.indexOf(S.p);
  if (i + 1 < PUZZLES.length) {
    const b = Object.assign(document.createElement('button'), { type: 'button', className: 'next-puzzle', textContent: `Next puzzle: ${PUZZLES[i + 1].title} →` });
    b.addEventListener('click', () => open(PUZZLES[i + 1].id, null));
    el.append(' ', b);
  }
}

function showLog() {
  $('puzzle-log').replaceChildren(
    ...S.steps.map((s, k) => {
      const li = document.createElement('li');
      li.append(Object.assign(document.createElement('span'), { textContent: stepText(s) }));
      li.append(Object.assign(document.createElement('small'), { textContent: ` — ${effectText(S.reports[k])}` }));
      return li;
    }),
  );
  $('puzzle-oplog').textContent = ['v1', ...S.steps].join(';');
  $('puzzle-undo').disabled = S.steps.length === 0;
}

function showHints() {
  $('puzzle-hints').replaceChildren(...S.p.hints.slice(0, S.hints).map((h) => Object.assign(document.createElement('li'), { textContent: h })));
  $('puzzle-hint').disabled = S.hints >= S.p.hints.length;
}

// The next step of the known answer when the steps so far follow it (compared by canonical hash).
function nextStep() {
  const hashes = [S.refHashes[0]];
  const m = meshAfter(S.p.mesh, S.p.pre);
  try {
    for (const s of S.steps) hashes.push((m.apply(s), m.canonicalHash()));
  } finally {
    m.delete();
  }
  let k = 0;
  while (k < hashes.length && k < S.refHashes.length && hashes[k] === S.refHashes[k]) k++;
  const out = $('puzzle-next-text');
  if (k < hashes.length) {
    S.next = null;
    out.textContent = `Your steps leave the known answer at step ${k}: undo back to ${k - 1 === 0 ? 'the start' : `step ${k - 1}`} to follow it.`;
  } else if (k >= S.prep.reference.length + 1) {
    out.textContent = 'You are at the goal of the known answer.';
  } else {
    const step = S.prep.reference[k - 1];
    const at = placeOf(step, S.fig.mesh);
    S.next = at.kind === 'hex' ? null : at;
    out.textContent = `Next: ${stepText(step)} — pick ${pickText(at)}${at.kind === 'hex' ? ' (Pick “hex”, or its crossing in the diagram)' : ''} and choose ${step.split(' ')[0]} (${step}).`;
  }
  drawMarks();
}

function listPuzzles() {
  $('puzzle-list').replaceChildren(
    ...PUZZLES.map((p) => {
      const b = Object.assign(document.createElement('button'), { type: 'button', className: 'puzzle-chip' });
      b.dataset.puzzle = p.id;
      const solved = progress.solved(p.id);
      b.textContent = `${p.level}. ${p.title}${solved !== null ? ` ✓ ${solved}` : ''}`;
      b.setAttribute('aria-current', String(p === S.p));
      b.addEventListener('click', () => open(p.id, null));
      return b;
    }),
  );
  watchPuzzleList();
  revealCurrentPuzzle();
  requestAnimationFrame(revealCurrentPuzzle); // after layout, when a puzzle opens from the URL
}

// On a phone the list is one scrolling row: bring the current puzzle into it (also when the width
// changes, e.g. a phone turned, and the row starts or stops scrolling).
function revealCurrentPuzzle() {
  const list = $('puzzle-list');
  revealInStrip(list, list.querySelector('[aria-current=true]'), 12);
}
let watchingList = false;
function watchPuzzleList() {
  if (watchingList || typeof ResizeObserver === 'undefined') return;
  watchingList = true;
  new ResizeObserver(() => revealCurrentPuzzle()).observe($('puzzle-list'));
}

/** Opens a puzzle with steps (from the URL or storage); steps the engine refuses are dropped. */
function open(id, steps) {
  const p = PUZZLES.find((x) => x.id === id) || PUZZLES[0];
  S.p = p;
  S.prep = preparePuzzle(p, eng);
  S.refHashes = [];
  const ref = meshAfter(p.mesh, p.pre);
  S.refHashes.push(ref.canonicalHash());
  for (const s of S.prep.reference) S.refHashes.push((ref.apply(s), ref.canonicalHash()));
  ref.delete();
  Object.assign(S, { steps: [], reports: [], pick: null, hover: null, hints: 0, next: null });
  $('puzzle-title').textContent = `${p.level}. ${p.title}`;
  $('puzzle-goal').textContent = p.goal;
  $('puzzle-next-text').textContent = '';
  $('puzzle-typed-result').textContent = '';
  $('puzzle-typed').value = ''; // typed steps name another puzzle's hexes
  showHints();
  makeFigure(p);
  const wanted = steps ?? progress.steps(p.id);
  for (const s of wanted) if (!apply(s, true)) break;
  refresh(false);
}

function applyTyped() {
  const out = $('puzzle-typed-result');
  const steps = parseTyped($('puzzle-typed').value);
  let n = 0;
  for (const s of steps) {
    if (!apply(s, true)) {
      refresh();
      return void (out.textContent = `applied ${n}; ${S.error}`);
    }
    n++;
  }
  refresh();
  out.textContent = n ? `applied ${n} step${n === 1 ? '' : 's'}` : 'type at least one step';
}

$('puzzle-undo').addEventListener('click', () => {
  S.steps = S.steps.slice(0, -1);
  S.reports = S.reports.slice(0, -1);
  refresh();
});
$('puzzle-reset').addEventListener('click', () => {
  S.steps = [];
  S.reports = [];
  refresh();
});
$('puzzle-hint').addEventListener('click', () => {
  S.hints++;
  showHints();
});
$('puzzle-next').addEventListener('click', nextStep);
$('puzzle-apply-typed').addEventListener('click', applyTyped);
for (const r of document.querySelectorAll('input[name=pick]')) r.addEventListener('change', () => S.fig.view && drawMarks());

startPage(() => {
  const want = parsePuzzleHash(location.hash);
  open(want.id ?? progress.current ?? PUZZLES[0].id, want.id ? want.steps ?? [] : null);
  window.addEventListener('hashchange', () => {
    const h = parsePuzzleHash(location.hash);
    if (h.id && (h.id !== S.p.id || (h.steps ?? []).join(';') !== S.steps.join(';'))) open(h.id, h.steps ?? []);
  });
  // For the browser tests (they play by pointer; this only reads).
  window.tutorial.puzzle = {
    get id() { return S.p.id; },
    get steps() { return [...S.steps]; },
    get pick() { return S.pick; },
    get best() { return S.prep.best; },
    get reference() { return [...S.prep.reference]; },
    get figure() { return S.fig; },
    get candidates() { return S.lastCandidates ?? []; },
    puzzles: PUZZLES.map((p) => p.id),
  };
});
