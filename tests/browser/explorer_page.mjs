// Helpers for driving the explorer page in the browser tests: open a URL hash, wait for frames,
// read the shown counts and the app state, project hexes to the page, read canvas pixels.
import { execFileSync } from 'node:child_process';
import { join } from 'node:path';
import { root, startServer, startBrowser } from './harness.mjs';

export function cli(...args) {
  return execFileSync(join(root, 'build/native/hexdual'), args).toString();
}

/** A server, a browser and one page whose uncaught errors collect in `errors`. */
export async function openBrowser() {
  const server = await startServer();
  const context = await startBrowser();
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  return { server, context, page, errors, close: async () => (await context.close(), server.stop()) };
}

/** Explorer helpers bound to one page and server. */
export function explorerPage(page, server) {
  // The step animation (if any) has ended and two more frames are drawn: the view shows the state.
  const settle = () => page.evaluate(async () => {
    const frame = () => new Promise((r) => requestAnimationFrame(r));
    const diagramsMove = () => [...(window.hexdual?.diagrams?.panels.values() ?? [])].some((p) => p.animating);
    while (window.hexdual?.view?.animating || diagramsMove()) await frame();
    await frame();
    await frame();
  });
  return {
    settle,
    async open(hash) {
      await page.goto('about:blank');
      await page.goto(server.url + hash);
      await page.waitForFunction(() => window.hexdual?.ready === true, null, { timeout: 60000 });
      await settle();
    },
    shownCounts: () => page.$$eval('[data-count]', (tds) => Object.fromEntries(tds.map((td) => [td.dataset.count, Number(td.textContent)]))),
    state: () => page.evaluate(() => {
      const s = window.hexdual.store.get();
      return { steps: s.steps, at: s.at, selection: s.selection, report: s.report, diagrams: s.diagrams.map((d) => d.sheet), hexes: s.mesh.counts.hexes, error: s.error };
    }),
    /** Drops a file with this text on the page, as dragging it from the desktop does. */
    dropFile: (text, name) => page.evaluate(([text, name]) => {
      const dt = new DataTransfer();
      dt.items.add(new File([text], name));
      for (const type of ['dragenter', 'dragover', 'drop']) document.body.dispatchEvent(new DragEvent(type, { dataTransfer: dt, bubbles: true }));
    }, [text, name]),
    project: (hex, face) => page.evaluate(([h, f]) => window.hexdual.view.project(h, f), [hex, face]),
    hash: () => decodeURIComponent(new URL(page.url()).hash).replace(/\+/g, ' '),
    // RGBA pixels of a canvas region (page coordinates, CSS px).
    pixels: (x, y, w, h) => page.evaluate(([x, y, w, h]) => {
      const c = window.hexdual.view.canvas;
      const r = c.getBoundingClientRect();
      const sx = c.width / r.width;
      const tmp = document.createElement('canvas');
      tmp.width = Math.round(w * sx);
      tmp.height = Math.round(h * sx);
      const g = tmp.getContext('2d');
      g.drawImage(c, (x - r.left) * sx, (y - r.top) * sx, w * sx, h * sx, 0, 0, tmp.width, tmp.height);
      return Array.from(g.getImageData(0, 0, tmp.width, tmp.height).data);
    }, [x, y, w, h]),
  };
}

/** How many pixels of two equal-sized RGBA arrays differ clearly. */
export function differing(a, b) {
  let n = 0;
  for (let i = 0; i < a.length; i += 4) if (Math.abs(a[i] - b[i]) + Math.abs(a[i + 1] - b[i + 1]) + Math.abs(a[i + 2] - b[i + 2]) > 40) n++;
  return n;
}
