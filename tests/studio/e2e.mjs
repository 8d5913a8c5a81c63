// End-to-end test of the studio (issue 7): starts `ramus serve` on a free loopback port and
// drives the page in Debian's headless Chromium with playwright-core.
//
//   node tests/studio/e2e.mjs RAMUS_BINARY OUTPUT_DIR
//
// Opens the page, generates a skeleton with 4 legs and checks the canvas shows a model (not a
// blank view), switches to L-systems, loads a preset, generates it, introduces a syntax error
// and checks it is reported at its line, grows a colonization preset with its points, and
// downloads a GLB into OUTPUT_DIR (the glTF validator checks it afterwards). Exits 1 on failure.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import process from 'node:process';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

const [binary, outputDir] = process.argv.slice(2);
if (!binary || !outputDir) {
  console.error('usage: node tests/studio/e2e.mjs RAMUS_BINARY OUTPUT_DIR');
  process.exit(2);
}
const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const kTimeout = 60_000;

function startServer() {
  const server = spawn(binary, ['serve', '--port', '0', '--root', root], { stdio: ['ignore', 'pipe', 'inherit'] });
  return new Promise((resolve, reject) => {
    let out = '';
    server.stdout.on('data', (chunk) => {
      out += chunk;
      const match = /http:\/\/[^\s]+/.exec(out);
      if (match) resolve({ server, url: match[0] });
    });
    server.on('exit', (code) => reject(new Error(`ramus serve exited with ${code}`)));
  });
}

/** Pixels of the 3D canvas that differ clearly from the background colour. */
async function modelPixels(page) {
  return page.evaluate(() => {
    const gl = document.querySelector('#canvas-host canvas');
    const c = document.createElement('canvas');
    c.width = gl.width;
    c.height = gl.height;
    const ctx = c.getContext('2d');
    ctx.drawImage(gl, 0, 0);
    const { data } = ctx.getImageData(0, 0, c.width, c.height);
    const bg = [0x2b, 0x2f, 0x33];
    let count = 0;
    for (let i = 0; i < data.length; i += 4) {
      const d = Math.abs(data[i] - bg[0]) + Math.abs(data[i + 1] - bg[1]) + Math.abs(data[i + 2] - bg[2]);
      if (d > 60) ++count;
    }
    return count;
  });
}

async function waitForStatus(page, pattern) {
  await page.waitForFunction(
    (source) => new RegExp(source).test(document.getElementById('status').textContent),
    pattern.source, { timeout: kTimeout });
  return page.textContent('#status');
}

const checks = [];
function check(name, ok, detail = '') {
  checks.push({ name, ok });
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}${detail ? ' — ' + detail : ''}`);
}

async function run(page, url) {
  await page.goto(url);
  await page.waitForSelector('body[data-ready="true"]', { timeout: kTimeout });

  // Skeleton with 4 legs: a model appears.
  await page.fill('#sk-legs', '4');
  await page.fill('#sk-seed', '5');
  await page.click('#sk-generate');
  let status = await waitForStatus(page, /done|error/);
  check('skeleton generated', status.startsWith('done'), status);
  await page.waitForTimeout(500);
  const pixels = await modelPixels(page);
  check('canvas shows the skeleton', pixels > 2000, `${pixels} model pixels`);
  const bones = await page.locator('#bone-tree span').count();
  check('bone hierarchy listed', bones > 20, `${bones} bones`);
  await page.locator('#bone-tree span').nth(3).click();
  check('clicking a bone selects it', (await page.locator('#bone-tree span.selected').count()) === 1);

  // Download the GLB.
  const [download] = await Promise.all([page.waitForEvent('download'), page.click('#dl-glb')]);
  const glbPath = path.join(outputDir, 'studio_e2e_skeleton.glb');
  await download.saveAs(glbPath);
  const glb = fs.readFileSync(glbPath);
  check('GLB downloaded', glb.subarray(0, 4).toString() === 'glTF', `${glb.length} bytes`);

  // L-systems: a preset, then a syntax error reported at its line.
  await page.click('#tab-lsystem');
  await page.selectOption('#ls-preset', 'koch_island');
  await page.click('#ls-generate');
  status = await waitForStatus(page, /done|error/);
  check('L-system preset generated', status.startsWith('done'), status);
  // The bark options: a dense plant welded is not one surface, and the status says so.
  await page.selectOption('#ls-preset', 'abop_1_27');
  await page.check('#ls-weld');
  await page.click('#ls-generate');
  status = await waitForStatus(page, /done|error/);
  check('welded bark warns of pieces', status.includes('not one clean surface'), status);
  // Convex junctions: the request carries the option, and the reply counts no shrunk junction.
  await page.check('#ls-convex');
  const convexReply = page.waitForResponse((r) => r.url().endsWith('/api/lsystem'));
  await page.click('#ls-generate');
  const convexBody = await (await convexReply).json();
  status = await waitForStatus(page, /done|error/);
  check('convex junctions keep the hulls', convexBody.stats?.weld_shrunk_junctions === 0,
        JSON.stringify(convexBody.stats));
  await page.uncheck('#ls-convex');
  await page.uncheck('#ls-weld');
  await page.selectOption('#ls-preset', 'koch_island');
  const text = await page.inputValue('#ls-text');
  const errorLine = text.split('\n').length + 1;
  await page.fill('#ls-text', `${text}\nX -> F(+\n`);
  await page.click('#ls-generate');
  status = await waitForStatus(page, /done|input\.lsys/);
  check('syntax error reported', status.includes(`input.lsys:${errorLine}:`), status);
  const marked = await page.getAttribute('#ls-gutter .error-line', 'data-line').catch(() => null);
  check('error marked at its line', marked === String(errorLine), `gutter line ${marked}`);

  // Colonization: a tree and its attraction points.
  await page.click('#tab-colonize');
  await page.selectOption('#co-preset', 'broadleaf');
  await page.click('#co-generate');
  status = await waitForStatus(page, /done|error/);
  check('colonization generated', status.startsWith('done'), status);
  const points = await page.evaluate(() => window.ramusStudio.viewer.points?.geometry.attributes.position.count ?? 0);
  check('attraction points shown', points > 100, `${points} points`);
}

fs.mkdirSync(outputDir, { recursive: true });
const { server, url } = await startServer();
let browser;
try {
  browser = await chromium.launch({
    executablePath: process.env.CHROMIUM ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader'],
  });
  const page = await browser.newPage({ viewport: { width: 1400, height: 900 }, acceptDownloads: true });
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await run(page, url);
  await page.screenshot({ path: path.join(outputDir, 'studio_e2e.png') });
  check('no script errors on the page', errors.length === 0, errors.join('; '));
} catch (e) {
  check('studio end-to-end run', false, e.message);
} finally {
  await browser?.close();
  server.kill('SIGTERM');
}
const failed = checks.filter((c) => !c.ok).length;
console.log(`studio e2e: ${checks.length - failed} passed, ${failed} failed`);
process.exit(failed === 0 ? 0 : 1);
