// Bundles the page into OUTDIR (index.html + app.js) with esbuild: `node build.mjs OUTDIR`.
// Without node_modules (npm ci not run) it says so and exits 0, so that a build without the
// front end still succeeds; `mechsim view` then says the page was not built.
import { copyFileSync, mkdirSync, existsSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const outdir = process.argv[2];
if (!outdir) {
  console.error('usage: node build.mjs OUTDIR');
  process.exit(2);
}
if (!existsSync(join(here, 'node_modules', 'esbuild')) || !existsSync(join(here, 'node_modules', 'three'))) {
  console.warn(`mechsim web: ${join(here, 'node_modules')} is missing (run scripts/install-deps.sh or npm ci in web/): ` +
               'the replay page is not built');
  process.exit(0);
}
const esbuild = await import('esbuild');
mkdirSync(outdir, { recursive: true });
await esbuild.build({
  entryPoints: [join(here, 'src', 'main.js')],
  bundle: true,
  minify: true,
  format: 'iife',
  target: ['es2020'],
  outfile: join(outdir, 'app.js'),
  logLevel: 'warning',
  legalComments: 'none',
});
copyFileSync(join(here, 'index.html'), join(outdir, 'index.html'));
