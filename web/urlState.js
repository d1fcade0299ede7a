// Shareable state in the URL hash, e.g. #mesh=grid:3x3x3&sheet=2. Garbage is ignored with a message.
const DIMS = /^(grid|ring):(\d{1,3})x(\d{1,3})x(\d{1,3})$/;

export function parseHash(hash) {
  const out = { mesh: { kind: 'grid', dims: [3, 3, 3] }, selection: null, ops: [], errors: [] };
  const params = new URLSearchParams(hash.replace(/^#/, ''));
  const mesh = params.get('mesh');
  if (mesh === 'fourcube') {
    out.mesh = { kind: 'fourcube', dims: [] };
  } else if (mesh !== null) {
    const m = DIMS.exec(mesh);
    if (m) out.mesh = { kind: m[1], dims: [Number(m[2]), Number(m[3]), Number(m[4])] };
    else out.errors.push(`ignored mesh=${mesh}: expected grid:AxBxC, ring:NxRxZ or fourcube`);
  }
  const ops = params.get('ops');
  if (ops !== null) {
    const steps = ops.split(';');
    if (steps[0] === 'v1') out.ops = steps.slice(1).filter((x) => x.length > 0);
    else out.errors.push(`ignored ops=${ops}: an operation log starts with v1`);
  }
  for (const kind of ['sheet', 'chord']) {
    const v = params.get(kind);
    if (v === null) continue;
    if (/^\d{1,7}$/.test(v)) out.selection = { kind, id: Number(v) };
    else out.errors.push(`ignored ${kind}=${v}: expected a number`);
  }
  return out;
}

export function formatHash({ mesh, selection, ops = [] }) {
  const params = new URLSearchParams();
  if (mesh && mesh.kind === 'fourcube') params.set('mesh', 'fourcube');
  else if (mesh && mesh.kind !== 'file') params.set('mesh', `${mesh.kind}:${mesh.dims.join('x')}`);
  if (ops.length) params.set('ops', ['v1', ...ops].join(';'));
  if (selection) params.set(selection.kind, String(selection.id));
  return '#' + params.toString();
}
