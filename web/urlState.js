// The whole screen in the URL hash: mesh, steps, position in the timeline, selection, camera,
// open diagrams and view toggles, e.g.
//   #mesh=grid:3x3x3&steps=v1;pillow h13f5&at=1&sel=h13f5&cam=…&diag=4,7
// Anything malformed is ignored with a message naming the parameter.
import { parseSelection, formatSelection } from './selection.js';

const DIMS = /^(grid|ring):(\d{1,3})x(\d{1,3})x(\d{1,3})$/;
const KNOWN = new Set(['mesh', 'steps', 'ops', 'at', 'sel', 'sheet', 'chord', 'cam', 'diag', 'local', 'overlay', 'sing', 'color', 'shrink', 'slice', 'ghosts', 'view', 'flip']);

/**
 * An operation log as typed, pasted or saved by "download .hxd + steps": 'v1;pillow h13f5;...' or
 * its URL form '1.P13f5...', optionally followed (after a newline or a space) by 'at=K', the
 * position to show. Returns { log, at } (at null when absent), or null when the text is one step.
 */
export function parseStepLog(text) {
  const t = text.trim();
  const m = /^([\s\S]*?)(?:\s+at=(\d{1,6}))?$/.exec(t);
  const log = m[1].replace(/\s*\n\s*/g, ';').trim();
  if (!/^v1(;|$)/.test(log) && !/^1\./.test(log)) return null;
  return { log, at: m[2] === undefined ? null : +m[2] };
}

export function parseHash(hash) {
  const out = {
    mesh: { kind: 'grid', dims: [3, 3, 3] }, steps: [], at: null, selection: null, camera: null, diagrams: [],
    overlay: false, singular: false, colorBy: 'plain', shrink: null, slice: null, ghosts: true, view: 'explore', flip: null, errors: [],
  };
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const ignore = (k, v, why) => out.errors.push(`ignored ${k}=${v}: ${why}`);
  for (const [k, v] of params) {
    switch (k) {
      case 'mesh': {
        const m = DIMS.exec(v);
        if (v === 'fourcube') out.mesh = { kind: 'fourcube', dims: [] };
        else if (m) out.mesh = { kind: m[1], dims: [+m[2], +m[3], +m[4]] };
        else if (v.startsWith('file:')) out.mesh = { kind: 'file', name: v.slice(5) };
        else ignore(k, v, 'expected grid:AxBxC, ring:NxRxZ, fourcube or file:NAME');
        break;
      }
      case 'steps':
      case 'ops': {
        const steps = v.split(';');
        if (steps[0] === 'v1') out.steps = steps.slice(1).filter((x) => x.length > 0);
        else ignore(k, v, 'an operation log starts with v1');
        break;
      }
      case 'at':
        if (/^\d{1,6}$/.test(v)) out.at = +v;
        else ignore(k, v, 'expected a step number');
        break;
      case 'sel': {
        const s = parseSelection(v);
        if (s) out.selection = s;
        else ignore(k, v, 'expected h13, h13f5, h13e4, s4 or c7');
        break;
      }
      case 'sheet':
      case 'chord':
        if (/^\d{1,7}$/.test(v)) out.selection = { kind: k, id: +v };
        else ignore(k, v, 'expected a number');
        break;
      case 'cam': {
        const c = v.split(',').map(Number);
        if (c.length === 6 && c.every(Number.isFinite)) out.camera = c;
        else ignore(k, v, 'expected six numbers (camera position and target)');
        break;
      }
      case 'diag': {
        const ids = v.split(',');
        if (ids.every((x) => /^\d{1,7}$/.test(x))) out.diagrams = ids.map(Number);
        else ignore(k, v, 'expected sheet ids separated by commas');
        break;
      }
      case 'sing':
        out.singular = v === '1';
        if (v !== '1' && v !== '0') ignore(k, v, 'expected 0 or 1');
        break;
      case 'overlay':
        out.overlay = v === '1';
        if (v !== '1' && v !== '0') ignore(k, v, 'expected 0 or 1');
        break;
      case 'ghosts':
        out.ghosts = v !== '0';
        if (v !== '1' && v !== '0') ignore(k, v, 'expected 0 or 1');
        break;
      case 'color':
        if (v === 'quality' || v === 'plain') out.colorBy = v;
        else ignore(k, v, 'expected quality or plain');
        break;
      case 'shrink':
        if (/^0(\.\d+)?$/.test(v) && +v <= 0.9) out.shrink = +v;
        else ignore(k, v, 'expected a number from 0 to 0.9');
        break;
      case 'slice': {
        const m = /^([xyz]):(0(\.\d+)?|1)$/.exec(v);
        if (m) out.slice = { axis: 'xyz'.indexOf(m[1]), at: +m[2] };
        else ignore(k, v, 'expected x|y|z:FRACTION, e.g. z:0.5');
        break;
      }
      case 'view':
        if (v === 'explore' || v === 'flips') out.view = v;
        else ignore(k, v, 'expected explore or flips');
        break;
      case 'flip':
        out.flip = v;
        break;
      default:
        if (!KNOWN.has(k)) ignore(k, v, 'unknown parameter');
    }
  }
  return out;
}

export function meshParam(spec) {
  if (!spec) return null;
  if (spec.kind === 'fourcube') return 'fourcube';
  if (spec.kind === 'file') return `file:${spec.name}`;
  return `${spec.kind}:${spec.dims.join('x')}`;
}

export function formatHash(s) {
  const params = new URLSearchParams();
  const mesh = meshParam(s.spec);
  if (mesh) params.set('mesh', mesh);
  if (s.steps && s.steps.length) {
    params.set('steps', ['v1', ...s.steps].join(';'));
    if (s.at !== s.steps.length) params.set('at', String(s.at));
  }
  if (s.selection) params.set('sel', formatSelection(s.selection));
  if (s.diagrams && s.diagrams.length) params.set('diag', s.diagrams.map((d) => d.sheet).join(','));
  if (s.overlay) params.set('overlay', '1');
  if (s.singular) params.set('sing', '1');
  if (s.colorBy === 'quality') params.set('color', 'quality');
  if (s.shrink !== 0.15) params.set('shrink', String(s.shrink));
  if (s.slice) params.set('slice', `${'xyz'[s.slice.axis]}:${s.slice.at}`);
  if (!s.ghosts) params.set('ghosts', '0');
  if (s.view === 'flips') params.set('view', 'flips');
  if (s.flip) params.set('flip', s.flip);
  if (s.camera) params.set('cam', s.camera.join(','));
  return '#' + params.toString();
}
