// The build: one page, a module worker for MuJoCo, hashed assets in dist/assets/.
import { defineConfig } from 'vite';

export default defineConfig({
  build: {
    target: 'es2022',
    outDir: 'dist',
    assetsInlineLimit: 0,
    chunkSizeWarningLimit: 1024,
    sourcemap: false,
  },
  worker: { format: 'es' },
});
