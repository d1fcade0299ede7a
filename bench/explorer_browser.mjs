// Explorer load and frame times in headless Chromium (software GL, SwiftShader): time from
// navigation to the first drawn frame, the time to select a sheet (colours only, no geometry), a
// camera-move frame, and a hover pick. Usage: node bench/explorer_browser.mjs [grid dims ...]
// (needs the web build: npx vite build web). With COMPARE=DIR, each size is also measured on the
// page built in DIR/dist (e.g. an older web/ checked out there), alternating, in the same run.
import { startServer, startBrowser } from '../tests/browser/harness.mjs';

const sizes = process.argv.slice(2).length ? process.argv.slice(2) : ['10x10x10', '30x30x30', '47x47x47'];
const pages = ['web', ...(process.env.COMPARE ? [process.env.COMPARE] : [])];
const servers = await Promise.all(pages.map((dir) => startServer(dir)));
const context = await startBrowser();
const page = await context.newPage();
const parts = [];
try {
  console.log('| page | mesh | hexes | drawn hexes | navigation to first frame (ms) | wasm init (ms) | mesh + all views (ms) | of which 3D geometry (ms) | select a sheet, to next frame (ms) | colour update, CPU (ms) | camera frame, CPU (ms) | camera frame, to screen (ms) | pick (ms) |');
  console.log('| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |');
  for (const dims of sizes) for (const [which, server] of servers.entries()) {
    await page.goto('about:blank');
    const t0 = Date.now();
    await page.goto(`${server.url}#mesh=grid:${dims}`);
    await page.waitForFunction(() => window.hexdual?.ready === true && window.hexdual.view.frames > 0, null, { timeout: 120000 });
    const load = Date.now() - t0;
    const r = await page.evaluate(async () => {
      const { view, actions, store } = window.hexdual;
      const frame = () => new Promise((res) => requestAnimationFrame(() => requestAnimationFrame(res)));
      await frame();
      const f0 = view.frames;
      const tm = window.hexdual.timings;
      const first = { ...tm };
      let t = performance.now();
      const v0 = tm.view;
      actions.select({ kind: 'sheet', id: 1 });
      const colours = tm.view - v0;
      await frame();
      const select = performance.now() - t;
      actions.select(null);
      await frame();
      // Camera moves, each until the frame is on screen (two animation frames: SwiftShader's time).
      const c = view.getCamera();
      t = performance.now();
      for (let i = 1; i <= 5; i++) {
        view.setCamera([c[0] * (1 + 0.01 * i), c[1], c[2], c[3], c[4], c[5]]);
        await frame();
      }
      const cameraToScreen = (performance.now() - t) / 5;
      const camera = view.lastFrameMs;
      const rect = view.canvas.getBoundingClientRect();
      t = performance.now();
      view.pickAt(rect.left + rect.width / 2, rect.top + rect.height / 2);
      const pick = performance.now() - t;
      return { hexes: store.get().mesh.counts.hexes, drawn: view.triangleCount / 12, build: view.lastBuildMs, select, colours, camera, cameraToScreen, pick, frames: view.frames - f0,
        init: tm.init - tm.start, loaded: tm.loaded - tm.urlStart,
        // Where the load went (CPU, ms): the mesh in wasm, then each view's first update.
        parts: { mesh: window.hexdual.engine.buildMs, view3d: first.view, panel: first.panel, diagrams: first.diagrams, timeline: first.timeline, palette: first.palette } };
    });
    const f = (x) => x.toFixed(0);
    parts.push(`| ${pages[which]} | grid:${dims} | ${Object.values(r.parts).map(f).join(' | ')} |`);
    console.log(`| ${pages[which]} | grid:${dims} | ${r.hexes} | ${r.drawn} | ${load} | ${f(r.init)} | ${f(r.loaded)} | ${f(r.build)} | ${f(r.select)} | ${f(r.colours)} | ${f(r.camera)} | ${f(r.cameraToScreen)} | ${f(r.pick)} |`);
  }
  console.log('\n| page | mesh | build mesh in wasm (ms) | 3D view (ms) | panel and lists (ms) | diagrams (ms) | timeline (ms) | palette (ms) |');
  console.log('| --- | --- | ---: | ---: | ---: | ---: | ---: | ---: |');
  for (const p of parts) console.log(p);
} finally {
  await context.close();
  for (const server of servers) server.stop();
}
