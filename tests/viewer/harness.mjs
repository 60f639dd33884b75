// What the browser tests share: their arguments, checks, `maquette view` on a folder, Debian's
// chromium driven by playwright-core (headless, WebGL through SwiftShader), waiting for a page's
// "loaded" signal, and the terrain pixels of a screenshot.
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync } from 'node:fs';
import { createRequire } from 'node:module';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

export const SKIP = 77;
const t0 = Date.now();
export const log = (...m) => console.log(`[${((Date.now() - t0) / 1000).toFixed(1)}s]`, ...m);

// --name value pairs.
export function parseArgs(argv = process.argv) {
  const args = {};
  for (let i = 2; i < argv.length; i += 2) args[argv[i].replace(/^--/, '')] = argv[i + 1];
  return args;
}

export class Checks {
  failures = [];

  check(ok, what) {
    log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
    if (!ok) this.failures.push(what);
    return ok;
  }
}

// The npm packages of the tests (playwright-core, pngjs, ...) from NODE_MODULES.
export function requireFrom(nodeModules) {
  return createRequire(join(resolve(nodeModules), '..', 'package.json'));
}

// `maquette view DIR --port 0`: resolves to { url, stop } once it prints its URL; stop() sends
// SIGINT and resolves to whether it exited cleanly.
export async function startView(maquette, dir, viewer) {
  const server = spawn(maquette, ['view', dir, '--port', '0', '--viewer', viewer],
    { stdio: ['ignore', 'pipe', 'pipe'] });
  let err = '';
  server.stderr.on('data', (d) => { err += d; });
  const url = await new Promise((resolveUrl, reject) => {
    let buf = '';
    const timer = setTimeout(() => reject(new Error(`maquette view printed no URL: ${buf}${err}`)), 10000);
    server.stdout.on('data', (d) => {
      buf += d;
      const m = buf.match(/http:\/\/127\.0\.0\.1:\d+\//);
      if (m) { clearTimeout(timer); resolveUrl(m[0]); }
    });
    server.on('exit', (code) => { clearTimeout(timer); reject(new Error(`maquette view exited (${code}): ${buf}${err}`)); });
  });
  log(`maquette view serves ${dir} at ${url}`);
  const stop = async () => {
    server.kill('SIGINT');
    await new Promise((r) => { if (server.exitCode !== null) r(); else server.on('exit', r); setTimeout(r, 3000); });
    if (server.exitCode !== 0) log(`maquette view did not stop cleanly on SIGINT (${server.exitCode}) ${err}`);
    return server.exitCode === 0;
  };
  return { url, stop };
}

// Debian's chromium (or MAQUETTE_CHROMIUM), headless, one page of `viewport`; the test is
// skipped (exit 77) without it. Records console errors, requests and failed requests.
export async function launchBrowser(nodeModules, viewport = { width: 960, height: 640 }) {
  const chromiumPath = process.env.MAQUETTE_CHROMIUM || '/usr/bin/chromium';
  if (!existsSync(chromiumPath)) {
    console.log(`SKIPPED: no Chromium at ${chromiumPath} (install the Debian package chromium, or set MAQUETTE_CHROMIUM)`);
    process.exit(SKIP);
  }
  const { chromium } = requireFrom(nodeModules)('playwright-core');
  const userDataDir = mkdtempSync(join(tmpdir(), 'maquette-chromium-'));
  const context = await chromium.launchPersistentContext(userDataDir, {
    executablePath: chromiumPath,
    headless: true,
    viewport,
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist',
      '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run',
      '--disable-dev-shm-usage'],
  });
  const page = context.pages()[0] || await context.newPage();
  const b = { context, page, consoleErrors: [], requests: [], badRequests: [] };
  page.on('console', (m) => { if (m.type() === 'error') b.consoleErrors.push(`${m.text()} ${m.location()?.url || ''}`); });
  page.on('pageerror', (e) => b.consoleErrors.push(String(e)));
  page.on('request', (r) => b.requests.push(r.url()));
  page.on('requestfailed', (r) => b.badRequests.push(`${r.url()} (${r.failure()?.errorText})`));
  page.on('response', (r) => { if (r.status() >= 400 && !/favicon/.test(r.url())) b.badRequests.push(`${r.url()} (HTTP ${r.status()})`); });
  b.close = async () => {
    await context.close().catch(() => {});
    rmSync(userDataDir, { recursive: true, force: true });
  };
  return b;
}

// Waits until the page sets data-tiles-loaded="true" (or data-error) on <html>; on a timeout,
// logs `diagnose()`'s answer, the console errors and failed requests, screenshots OUT/timeout-*.png
// and throws.
export async function waitLoaded(b, what, out, diagnose = () => null, timeout = 60000) {
  try {
    await b.page.waitForFunction(() => document.documentElement.dataset.tilesLoaded === 'true'
      || document.documentElement.dataset.error, null, { timeout, polling: 100 });
  } catch (e) {
    const diag = await b.page.evaluate(diagnose).catch((e2) => String(e2));
    log(`${what}: tiles never loaded: ${JSON.stringify(diag)}`);
    log(`console errors: ${b.consoleErrors.slice(0, 5).join(' | ') || 'none'}; failed requests: ${b.badRequests.slice(0, 5).join(' ') || 'none'}`);
    await b.page.screenshot({ path: join(out, `timeout-${what.replace(/\W+/g, '-')}.png`) }).catch(() => {});
    throw e;
  }
}

// The pixels of a screenshot saved as OUT/NAME (a pngjs PNG).
export async function shoot(b, out, name, PNG) {
  return PNG.sync.read(await b.page.screenshot({ path: join(out, name) }));
}

// Terrain pixels of a screenshot: those farther than 12 (any channel) from the background colour
// `bg`; their share of the frame, a mask, and their luminance's standard deviation.
export function terrainPixels(png, bg) {
  const n = png.width * png.height;
  const mask = new Uint8Array(n);
  let count = 0, sum = 0, sum2 = 0;
  for (let i = 0; i < n; i++) {
    const [r, g, b] = [png.data[4 * i], png.data[4 * i + 1], png.data[4 * i + 2]];
    if (Math.max(Math.abs(r - bg[0]), Math.abs(g - bg[1]), Math.abs(b - bg[2])) > 12) {
      mask[i] = 1; count++;
      const l = 0.3 * r + 0.59 * g + 0.11 * b; sum += l; sum2 += l * l;
    }
  }
  const sd = count ? Math.sqrt(Math.max(sum2 / count - (sum / count) ** 2, 0)) : 0;
  return { cover: count / n, mask, count, sd };
}

// The start of a page drawing a GLB with three.js (import map for /three/, a renderer filling
// the window, an empty scene with a sky-blue background): a picture script adds its lights, its
// loading of /scene.glb and its camera.
export const threePageStart = `<!doctype html><html><body style="margin:0">
<script type="importmap">{"imports": {"three": "/three/build/three.module.js",
  "three/addons/": "/three/examples/jsm/"}}</script>
<script type="module">
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/addons/loaders/DRACOLoader.js';
const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
renderer.setSize(innerWidth, innerHeight);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xbcd4e6);
const loader = new GLTFLoader();
const draco = new DRACOLoader();
draco.setDecoderPath('/three/examples/jsm/libs/draco/gltf/');
loader.setDRACOLoader(draco);
`;

// Serves `page` (HTML) from memory with /scene.glb (the file `glb`) and /three/... (three.js at
// `three`), waits until it sets data-loaded="true" or data-error on <html>, saves the screenshot
// as `out`, and exits 1 unless it drew at least `minMeshes` meshes (its data-meshes) without
// error.
export async function drawGlbPage({ nodeModules, three, glb, out, page, viewport, minMeshes = 2 }) {
  const b = await launchBrowser(nodeModules, viewport);
  await b.page.route('http://picture.test/**', (route) => {
    const path = new URL(route.request().url()).pathname;
    if (path === '/') return route.fulfill({ contentType: 'text/html', body: page });
    if (path === '/scene.glb') return route.fulfill({ contentType: 'model/gltf-binary', body: readFileSync(glb) });
    if (path.startsWith('/three/')) {
      const type = path.endsWith('.wasm') ? 'application/wasm' : 'text/javascript';
      return route.fulfill({ contentType: type, body: readFileSync(join(three, path.slice(7))) });
    }
    return route.fulfill({ status: 404 });
  });
  await b.page.goto('http://picture.test/');
  await b.page.waitForFunction(() => document.documentElement.dataset.loaded === 'true'
    || document.documentElement.dataset.error, null, { timeout: 120000 });
  const error = await b.page.evaluate(() => document.documentElement.dataset.error);
  const meshes = await b.page.evaluate(() => document.documentElement.dataset.meshes);
  await b.page.screenshot({ path: out });
  await b.close();
  if (error || b.consoleErrors.length || !(Number(meshes) >= minMeshes)) {
    log(`failed: ${error || ''} ${b.consoleErrors.join(' | ')} (${meshes} meshes)`);
    process.exit(1);
  }
  log(`${meshes} meshes drawn; saved ${out}`);
}
