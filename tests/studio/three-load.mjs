// Loads GLB files into three.js (issue 9): every .glb given goes through three.js's GLTFLoader
// in a real page in Debian's headless Chromium (playwright-core), with the studio's own three.js
// (web/node_modules/three, the version web/package-lock.json pins).
//
//   node tests/studio/three-load.mjs [--no-self-test] DIR_OR_FILE...
//
// Directories are searched recursively (sorted). All files are loaded in one page, in batches,
// one file at a time inside a batch. For each file:
//   - it parses with no error and no console warning or error from three.js / GLTFLoader;
//   - the scene has at least one mesh (files with no mesh in their glTF pass only when their
//     name says so: `empty`, the writer's empty-scene tests);
//   - every primitive of a skinned node is a THREE.SkinnedMesh bound to a THREE.Skeleton with
//     as many THREE.Bone as the glTF skin has joints (joint indices below that, finite inverse
//     bind matrices), and every skin is bound to a mesh;
//   - custom vertex attributes (`_WIND`, `_WIND_PIVOT`, `_WIND_LEAF`, any `_…`) arrive as
//     geometry attributes (lower-cased names, as GLTFLoader does) with one item per vertex;
//   - every `…_LOD<i>` node with a mesh arrives as an object holding a mesh;
//   - rendered fitted into view (like the studio's Viewer.frame) at 320×240, the canvas is not
//     blank: at least kMinPixels pixels differ from the background, and WebGL reports no error.
// A warning or error the browser itself prints (e.g. a WebGL error) fails the run too.
// Then a self-test (left out with --no-self-test): broken copies of two small files of the run
// (truncated, an unknown required extension, scaled to nothing, a skin one joint short) must
// each fail for its reason, so the check is known to be able to fail.
// Files over 50 MB are skipped with a note. Nothing is fetched from anywhere but the loopback
// server this script starts (any other request is blocked and fails the run). Prints one line
// per file and "three.js loaded N files: P passed, F failed, S skipped"; exits 1 on any failure
// or when no file was found. RAMUS_THREE_PNG=DIR also writes each render to DIR (to look at).
import fs from 'node:fs';
import http from 'node:http';
import os from 'node:os';
import path from 'node:path';
import process from 'node:process';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';
import { collectFiles } from '../common/collect_files.mjs';

const here = path.dirname(fileURLToPath(import.meta.url));
const root = path.resolve(here, '../..');
const threeDir = path.join(root, 'web/node_modules/three');
const kExtensions = new Set(['.glb']);
const kMaxBytes = 50 * 1024 * 1024;
const kBatchFiles = 16;
const kBatchBytes = 48 * 1024 * 1024;
const kBatchTimeout = 120_000;
const kMinPixels = 100; // of 320×240
const kTypes = {
  '.html': 'text/html', '.js': 'text/javascript', '.glb': 'model/gltf-binary',
  '.gltf': 'model/gltf+json', '.bin': 'application/octet-stream', '.png': 'image/png',
  '.jpg': 'image/jpeg', '.jpeg': 'image/jpeg', '.ktx2': 'image/ktx2', '.webp': 'image/webp',
};

/** `base/relative` when it stays inside base, else null. */
function inside(base, relative) {
  const full = path.resolve(base, relative);
  return full === base || full.startsWith(base + path.sep) ? full : null;
}

/**
 * Loopback server: the page (/), three.js (/three/…) and file i with the files next to it
 * (/files/i/NAME, so a .gltf's relative URIs resolve in its own directory).
 */
function startServer(files) {
  const server = http.createServer((req, res) => {
    const url = new URL(req.url, 'http://localhost');
    const p = decodeURIComponent(url.pathname);
    let full = null;
    if (p === '/') full = path.join(here, 'three-load.html');
    else if (p === '/three-load-page.js') full = path.join(here, 'three-load-page.js');
    else if (p.startsWith('/three/')) full = inside(threeDir, p.slice('/three/'.length));
    else {
      const m = /^\/files\/(\d+)\/(.+)$/.exec(p);
      const entry = m && files[Number(m[1])];
      if (entry) full = inside(path.dirname(path.resolve(entry.file)), m[2]);
    }
    if (!full || !fs.existsSync(full) || !fs.statSync(full).isFile()) {
      res.writeHead(404).end();
      return;
    }
    res.writeHead(200, { 'Content-Type': kTypes[path.extname(full).toLowerCase()] ?? 'application/octet-stream' });
    fs.createReadStream(full).pipe(res);
  });
  return new Promise((resolve) => server.listen(0, '127.0.0.1', () => resolve(server)));
}

/** What is wrong with a file, from the page's result; an empty list means ok. */
function judge(entry, r) {
  const failures = [];
  if (r.error) failures.push(`GLTFLoader: ${r.error}`);
  for (const w of r.warnings) failures.push(`console ${w}`);
  failures.push(...r.problems);
  if (r.error) return failures;
  const empty = r.gltfMeshes === 0 && /empty/i.test(path.basename(entry.file));
  if (r.meshes === 0 && !empty) failures.push('the scene has no mesh');
  if (!empty && r.box !== undefined && r.pixels < kMinPixels) {
    failures.push(`blank render: ${r.pixels} model pixels (box ${JSON.stringify(r.box)})`);
  }
  return failures;
}

function describe(r) {
  if (r.error) return '';
  const parts = [`${r.meshes} meshes`, `${Math.round(r.triangles)} triangles`];
  if (r.skins && r.skinned) {
    const bones = Object.values(r.skinned.joints);
    parts.push(`${r.skinned.found} skinned, ${r.skins} ${r.skins === 1 ? 'skin' : 'skins'} of ${bones.join('/') || 0} bones`);
  }
  if (r.custom?.expected) parts.push(`${r.custom.arrived}/${r.custom.expected} custom attributes (${r.custom.wind} _WIND*)`);
  if (r.lods?.expected) parts.push(`${r.lods.arrived}/${r.lods.expected} LODs`);
  parts.push(`${r.pixels} px`, `${r.ms} ms`);
  return parts.join(', ');
}

function batches(entries) {
  const out = [];
  let current = [];
  let bytes = 0;
  for (const e of entries) {
    if (current.length > 0 && (current.length >= kBatchFiles || bytes + e.bytes > kBatchBytes)) {
      out.push(current);
      current = [];
      bytes = 0;
    }
    current.push(e);
    bytes += e.bytes;
  }
  if (current.length > 0) out.push(current);
  return out;
}

function withTimeout(promise, ms, what) {
  let timer;
  return Promise.race([
    promise,
    new Promise((_, reject) => { timer = setTimeout(() => reject(new Error(`${what} timed out after ${ms / 1000} s`)), ms); }),
  ]).finally(() => clearTimeout(timer));
}

/** The JSON chunk of a GLB and its BIN chunk (or null); throws on a malformed container. */
function readGlb(bytes) {
  if (bytes.length < 20 || bytes.toString('latin1', 0, 4) !== 'glTF') throw new Error('not a GLB');
  const jsonLength = bytes.readUInt32LE(12);
  const json = JSON.parse(bytes.subarray(20, 20 + jsonLength).toString('utf8'));
  const rest = bytes.subarray(20 + jsonLength);
  return { json, bin: rest.length >= 8 ? rest.subarray(8, 8 + rest.readUInt32LE(0)) : null };
}

function writeGlb({ json, bin }) {
  let text = Buffer.from(JSON.stringify(json));
  text = Buffer.concat([text, Buffer.alloc((4 - (text.length % 4)) % 4, 0x20)]);
  const chunks = [Buffer.alloc(8), text];
  chunks[0].writeUInt32LE(text.length, 0);
  chunks[0].write('JSON', 4, 'latin1');
  if (bin) {
    const head = Buffer.alloc(8);
    head.writeUInt32LE(bin.length, 0);
    head.write('BIN\0', 4, 'latin1');
    chunks.push(head, bin);
  }
  const header = Buffer.alloc(12);
  header.write('glTF', 0, 'latin1');
  header.writeUInt32LE(2, 4);
  header.writeUInt32LE(12 + chunks.reduce((n, c) => n + c.length, 0), 8);
  return Buffer.concat([header, ...chunks]);
}

/**
 * The negative self-test: broken copies of two small files of the run (a skinned one and one
 * without skin), each of which the check must report as failed for the expected reason.
 */
function tamperedCopies(entries, dir) {
  const parsed = [];
  for (const e of entries.filter((x) => x.bytes < 4 * 1024 * 1024).sort((a, b) => a.bytes - b.bytes)) {
    try {
      const glb = readGlb(fs.readFileSync(e.file));
      if ((glb.json.meshes?.length ?? 0) > 0 && (glb.json.scenes?.length ?? 0) > 0) parsed.push({ e, glb });
    } catch {
      // not a well-formed GLB: the main run reports it
    }
  }
  const skinned = parsed.find((p) => p.glb.json.skins?.length > 0);
  const plain = parsed.find((p) => !p.glb.json.skins) ?? skinned;
  const copies = [];
  const add = (source, what, expect, change) => {
    const file = path.join(dir, `${what}_${path.basename(source.e.file)}`);
    fs.writeFileSync(file, change(structuredClone(source.glb), fs.readFileSync(source.e.file)));
    copies.push({ file, bytes: fs.statSync(file).size, what: `${what} copy of ${source.e.file}`, expect });
  };
  if (plain) {
    add(plain, 'truncated', /^GLTFLoader: /, (_, bytes) => bytes.subarray(0, Math.floor(bytes.length / 2)));
    add(plain, 'unknown_extension', /^console warn: .*Unknown extension/, (glb) => {
      glb.json.extensionsUsed = [...(glb.json.extensionsUsed ?? []), 'RAMUS_not_an_extension'];
      glb.json.extensionsRequired = [...(glb.json.extensionsRequired ?? []), 'RAMUS_not_an_extension'];
      return writeGlb(glb);
    });
    add(plain, 'zero_scale', /^blank render/, (glb) => {
      const scene = glb.json.scenes[glb.json.scene ?? 0];
      for (const n of scene.nodes) {
        delete glb.json.nodes[n].matrix;
        glb.json.nodes[n].scale = [0, 0, 0];
      }
      return writeGlb(glb);
    });
  }
  if (skinned) {
    add(skinned, 'one_joint_less', /joint index \d+ ≥ \d+ bones/, (glb) => {
      glb.json.skins[0].joints.pop();
      return writeGlb(glb);
    });
  }
  return copies;
}

async function main(args) {
  const selfTest = !args.includes('--no-self-test');
  args = args.filter((a) => a !== '--no-self-test');
  if (args.length === 0) {
    console.error('usage: node tests/studio/three-load.mjs [--no-self-test] DIR_OR_FILE...');
    return 2;
  }
  if (!fs.existsSync(path.join(threeDir, 'build/three.module.js'))) {
    console.error(`error: ${threeDir} is missing (run 'make deps')`);
    return 1;
  }
  const { files, unreadable } = collectFiles(args, kExtensions);
  const toLoad = files.filter((f) => f.bytes <= kMaxBytes);
  const tempDir = selfTest ? fs.mkdtempSync(path.join(os.tmpdir(), 'ramus-three-')) : null;
  const copies = selfTest ? tamperedCopies(toLoad, tempDir) : [];
  const served = [...files, ...copies];
  served.forEach((f, i) => { f.url = `/files/${i}/${encodeURIComponent(path.basename(f.file))}`; });
  const skipped = files.length - toLoad.length;
  for (const f of files) {
    if (f.bytes > kMaxBytes) console.log(`skip ${f.file}: ${(f.bytes / 1048576).toFixed(1)} MB > 50 MB`);
  }

  const pngDir = process.env.RAMUS_THREE_PNG;
  if (pngDir) fs.mkdirSync(pngDir, { recursive: true });
  const started = Date.now();
  const server = await startServer(served);
  const origin = `http://127.0.0.1:${server.address().port}`;
  const blocked = [];
  let passed = 0;
  let failed = 0;
  let runFailed = false; // the page, the browser or the network, not one file
  let browser;
  try {
    browser = await chromium.launch({
      executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
      args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
    });
    const context = await browser.newContext();
    // Only the loopback server: anything else (the internet, a CDN) is refused and reported.
    await context.route('**/*', (route) => {
      const url = route.request().url();
      if (url.startsWith(origin + '/')) return route.continue();
      blocked.push(url);
      return route.abort();
    });
    const page = await context.newPage();
    const pageErrors = [];
    page.on('pageerror', (e) => pageErrors.push(e.message));
    // The page records three.js's own warnings per file; what reaches the console is the
    // browser's (e.g. a WebGL error), reported with the batch it came up in.
    const browserMessages = [];
    let current = 'page start-up';
    page.on('console', (m) => {
      if (m.type() === 'warning' || m.type() === 'error') browserMessages.push(`${current}: ${m.type()}: ${m.text()}`);
    });
    await page.goto(origin + '/');
    await page.waitForSelector('body[data-ready="true"]', { state: 'attached', timeout: 60_000 });
    const startup = await page.evaluate(() => window.startupMessages());
    for (const m of startup) console.log(`note: page start-up: ${m}`);

    const load = async (entries, report) => {
      for (const batch of batches(entries)) {
        current = `batch from ${batch[0].file}`;
        const results = await withTimeout(
          page.evaluate((items) => window.checkFiles(items), batch.map((f) => ({ url: origin + f.url, png: Boolean(pngDir) }))),
          kBatchTimeout, `batch of ${batch.length} files from ${batch[0].file}`);
        batch.forEach((entry, i) => report(entry, results[i]));
      }
    };
    await load(toLoad, (entry, r) => {
      const failures = judge(entry, r);
      if (pngDir && r.png) {
        const name = `${files.indexOf(entry)}_${path.basename(entry.file, '.glb')}.png`;
        fs.writeFileSync(path.join(pngDir, name), Buffer.from(r.png.split(',')[1], 'base64'));
      }
      if (failures.length === 0) {
        ++passed;
        console.log(`ok   ${entry.file}: ${describe(r)}`);
      } else {
        ++failed;
        console.log(`FAIL ${entry.file}: ${describe(r)}`);
        for (const f of failures) console.log(`  ${f}`);
      }
    });
    await load(copies, (entry, r) => {
      const failures = judge(entry, r);
      const expected = failures.find((f) => entry.expect.test(f));
      if (expected) {
        console.log(`self-test ok   ${entry.what}: failed as it should (${expected})`);
      } else {
        console.log(`self-test FAIL ${entry.what}: ${failures.length ? failures.join('; ') : 'passed'}, expected a failure matching ${entry.expect}`);
        runFailed = true;
      }
    });
    if (selfTest && copies.length === 0) {
      console.log('self-test FAIL: no small well-formed GLB to make broken copies from');
      runFailed = true;
    }
    if (browserMessages.length > 0) {
      console.log('FAIL browser console messages:');
      for (const m of [...new Set(browserMessages)]) console.log(`  ${m}`);
      runFailed = true;
    }
    if (pageErrors.length > 0) {
      console.log(`FAIL script errors on the page: ${pageErrors.join('; ')}`);
      runFailed = true;
    }
  } catch (e) {
    console.log(`FAIL three.js load run: ${e.message}`);
    runFailed = true;
  } finally {
    await browser?.close();
    server.close();
    if (tempDir) fs.rmSync(tempDir, { recursive: true, force: true });
  }
  if (blocked.length > 0) {
    console.log(`FAIL requests outside the loopback server were blocked: ${[...new Set(blocked)].join(', ')}`);
    runFailed = true;
  }
  const seconds = ((Date.now() - started) / 1000).toFixed(1);
  const notLoaded = toLoad.length - passed - failed;
  console.log(`three.js loaded ${passed + failed} files: ${passed} passed, ${failed} failed, ` +
              `${skipped} skipped (> 50 MB)${notLoaded ? `, ${notLoaded} not reached` : ''}, ${seconds} s`);
  if (files.length === 0) {
    console.log('error: no .glb or .gltf files found');
    return 1;
  }
  return failed === 0 && notLoaded === 0 && !runFailed && unreadable === 0 ? 0 : 1;
}

process.exitCode = await main(process.argv.slice(2));
