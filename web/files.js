// Files: drop a mesh anywhere on the page; export a PNG of the 3D view with the state URL in a
// tEXt chunk ("hexdual-url"), the mesh in every writable format, and for a local file the start
// mesh as .hxd plus the steps, so the state can still be shared.
const FORMATS = [
  ['vtk', { binary: false }, 'vtk', 'VTK'],
  ['vtk', { binary: true }, 'vtk', 'VTK (binary)'],
  ['mesh', {}, 'mesh', 'Medit .mesh'],
  ['hxd', {}, 'hxd', '.hxd'],
];

function download(name, data, type) {
  const blob = data instanceof Blob ? data : new Blob([data], { type });
  const a = Object.assign(document.createElement('a'), { href: URL.createObjectURL(blob), download: name });
  document.body.appendChild(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(a.href), 2000);
}

// Mesh text from save(): binary VTK arrives as a byte string (one char per byte) or as bytes.
function bytesOf(saved) {
  if (saved instanceof Uint8Array) return saved;
  const out = new Uint8Array(saved.length);
  for (let i = 0; i < saved.length; i++) out[i] = saved.charCodeAt(i) & 255;
  return out;
}

const CRC_TABLE = (() => {
  const t = new Uint32Array(256);
  for (let n = 0; n < 256; n++) {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    t[n] = c >>> 0;
  }
  return t;
})();
function crc32(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) c = CRC_TABLE[(c ^ b) & 255] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

/** Inserts a PNG tEXt chunk (keyword, text) right after IHDR. */
export function pngWithText(png, keyword, text) {
  const data = new TextEncoder().encode(`${keyword}\0${text}`);
  const chunk = new Uint8Array(12 + data.length);
  const view = new DataView(chunk.buffer);
  view.setUint32(0, data.length);
  chunk.set([0x74, 0x45, 0x58, 0x74], 4); // 'tEXt'
  chunk.set(data, 8);
  view.setUint32(8 + data.length, crc32(chunk.subarray(4, 8 + data.length)));
  const ihdrEnd = 8 + 8 + 13 + 4;
  const out = new Uint8Array(png.length + chunk.length);
  out.set(png.subarray(0, ihdrEnd), 0);
  out.set(chunk, ihdrEnd);
  out.set(png.subarray(ihdrEnd), ihdrEnd + chunk.length);
  return out;
}

export function createFiles(body, actions, store, view) {
  const zone = document.getElementById('dropzone');
  let depth = 0;
  body.addEventListener('dragenter', (e) => {
    e.preventDefault();
    depth++;
    zone.hidden = false;
  });
  body.addEventListener('dragleave', () => {
    if (--depth <= 0) (depth = 0), (zone.hidden = true);
  });
  body.addEventListener('dragover', (e) => e.preventDefault());
  body.addEventListener('drop', async (e) => {
    e.preventDefault();
    depth = 0;
    zone.hidden = true;
    await actions.openFiles([...(e.dataTransfer?.files ?? [])]);
  });

  const exports = document.getElementById('exports');
  const button = (label, fn) => {
    const b = Object.assign(document.createElement('button'), { textContent: label });
    b.addEventListener('click', () => {
      try {
        fn();
      } catch (e) {
        actions.set({ error: e.message });
      }
    });
    exports.appendChild(b);
    return b;
  };
  const base = () => {
    const s = store.get();
    return s.spec?.kind === 'file' ? s.spec.name.replace(/(\.gz)?$/i, '').replace(/\.[^.]+$/, '') : s.spec?.kind === 'fourcube' ? 'fourcube' : `${s.spec.kind}-${s.spec.dims.join('x')}`;
  };
  button('PNG', () => {
    view.requestRender();
    requestAnimationFrame(() =>
      view.canvas.toBlob(async (blob) => {
        const png = new Uint8Array(await blob.arrayBuffer());
        download(`${base()}.png`, new Blob([pngWithText(png, 'hexdual-url', location.href)], { type: 'image/png' }));
      }, 'image/png'),
    );
  });
  for (const [format, opts, ext, label] of FORMATS) {
    button(label, () => download(`${base()}-step${store.get().at}.${ext}`, bytesOf(store.get().mesh.save(format, opts)), 'application/octet-stream'));
  }
  const hxdSteps = button('download .hxd + steps', () => {
    const s = store.get();
    const start = actions.engine.fileBytes();
    const { Mesh } = window.hexdual.pkg;
    const m = Mesh.load(start, s.spec.name);
    try {
      download(`${base()}.hxd`, bytesOf(m.save('hxd')), 'text/plain');
    } finally {
      m.delete();
    }
    download(`${base()}.steps.txt`, `${['v1', ...s.steps].join(';')}\nat=${s.at}\n`, 'text/plain');
  });
  return {
    update(s) {
      hxdSteps.hidden = s.spec?.kind !== 'file';
    },
  };
}
