// Vite builds the workbench into dist/ (static files served by `hula serve`);
// Vitest runs the unit tests of the browser-side math beside the sources.
import { defineConfig } from 'vitest/config';

export default defineConfig({
  base: './',
  build: { outDir: 'dist', emptyOutDir: true, sourcemap: false, chunkSizeWarningLimit: 1024 },
  test: { include: ['src/**/*.test.ts'], environment: 'node' },
});
