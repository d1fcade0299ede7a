import { defineConfig } from 'vite';
import { readdirSync } from 'node:fs';

const root = new URL('.', import.meta.url).pathname;
// Multi-page build: the explorer plus every tutorial page in tutorials/.
const tutorialPages = Object.fromEntries(
  readdirSync(new URL('./tutorials/', import.meta.url))
    .filter((f) => f.endsWith('.html'))
    .map((f) => [`tutorials/${f.replace(/\.html$/, '')}`, `${root}tutorials/${f}`]),
);

export default defineConfig({
  root,
  base: './',
  build: {
    outDir: 'dist',
    emptyOutDir: true,
    target: 'es2022',
    chunkSizeWarningLimit: 1000,
    rollupOptions: { input: { main: `${root}index.html`, ...tutorialPages } },
  },
  server: { fs: { allow: ['..'] } },
});
