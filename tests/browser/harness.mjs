// Serves the built demo with `vite preview` on a free localhost port and drives Debian's chromium.
import { spawn } from 'node:child_process';
import { mkdtempSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import net from 'node:net';
import { chromium } from 'playwright-core';

export const root = new URL('../../', import.meta.url).pathname;
export const screenshotDir = join(root, 'build', 'screenshots');

async function freePort() {
  return new Promise((resolve, reject) => {
    const srv = net.createServer();
    srv.listen(0, '127.0.0.1', () => {
      const { port } = srv.address();
      srv.close(() => resolve(port));
    });
    srv.on('error', reject);
  });
}

// `dir`: the page directory whose dist/ is served (benchmarks compare an older build).
export async function startServer(dir = 'web') {
  const port = await freePort();
  const proc = spawn(join(root, 'node_modules/.bin/vite'), ['preview', dir, '--host', '127.0.0.1', '--port', String(port), '--strictPort'], {
    cwd: root,
    stdio: ['ignore', 'pipe', 'pipe'],
  });
  const url = `http://127.0.0.1:${port}/`;
  for (let i = 0; i < 100; i++) {
    try {
      const r = await fetch(url);
      if (r.ok) return { url, stop: () => proc.kill('SIGTERM') };
    } catch {}
    await new Promise((r) => setTimeout(r, 100));
  }
  proc.kill('SIGTERM');
  throw new Error('vite preview did not start');
}

export async function startBrowser() {
  mkdirSync(screenshotDir, { recursive: true });
  const userDataDir = mkdtempSync(join(tmpdir(), 'hexdual-chromium-'));
  return chromium.launchPersistentContext(userDataDir, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    viewport: { width: 1200, height: 760 },
    args: [
      '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
      '--disable-component-update', '--disable-sync', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    ],
  });
}

/**
 * The server, a browser and one page for a test file, started before its tests and stopped after
 * them (`ready(session)` is called once they run); the page's uncaught errors and console errors
 * collect in `session.problems`.
 */
export function pageSession(before, after, ready) {
  const session = { server: null, context: null, page: null, problems: [] };
  before(async () => {
    session.server = await startServer();
    session.context = await startBrowser();
    session.page = await session.context.newPage();
    session.page.on('pageerror', (e) => session.problems.push(`pageerror: ${e.message}`));
    session.page.on('console', (m) => m.type() === 'error' && session.problems.push(`console: ${m.text()}`));
    ready(session);
  });
  after(async () => {
    await session.context?.close();
    session.server?.stop();
  });
  return session;
}
