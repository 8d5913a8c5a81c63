// The studio page: tabs, generation through the API, the 3D view, the bone tree, the gallery
// and downloads (docs/studio.md).
import { getExamples, post, decodeBase64, download, ApiError } from './api.js';
import { Viewer } from './viewer.js';
import { SkeletonPanel } from './skeleton_panel.js';
import { LsystemPanel } from './lsystem_panel.js';
import { ColonizePanel } from './colonize_panel.js';

const $ = (id) => document.getElementById(id);

/** What is shown: GLB bytes, a file name stem and, for skeletons, the metadata. */
let current = null;
let gallery = [];

function setStatus(text, isError = false) {
  $('status').textContent = text;
  $('status').classList.toggle('error', isError);
}

function setDownloads() {
  $('dl-glb').disabled = !current;
  $('dl-obj').disabled = !current;
  $('dl-png').disabled = !current;
  $('dl-meta').disabled = !current?.metadata;
}

/** The node tree of the shown skeleton; clicking a bone highlights it. */
function renderBoneTree(viewer, root) {
  const tree = $('bone-tree');
  tree.replaceChildren();
  const rootBone = root ? findFirstBone(root) : null;
  if (!rootBone) return;
  const add = (bone, list) => {
    const li = document.createElement('li');
    const label = document.createElement('span');
    label.textContent = bone.name;
    label.addEventListener('click', () => {
      for (const s of tree.querySelectorAll('.selected')) s.classList.remove('selected');
      label.classList.add('selected');
      viewer.highlight(bone);
    });
    li.append(label);
    const children = bone.children.filter((c) => c.isBone);
    if (children.length > 0) {
      const ul = document.createElement('ul');
      for (const c of children) add(c, ul);
      li.append(ul);
    }
    list.append(li);
  };
  add(rootBone, tree);
}

function findFirstBone(object) {
  if (object.isBone) return object;
  for (const c of object.children) {
    const found = findFirstBone(c);
    if (found) return found;
  }
  return null;
}

async function show(viewer, item, stats) {
  current = item;
  const root = await viewer.show(item.glb);
  renderBoneTree(viewer, item.metadata ? root : null);
  $('stats').textContent = JSON.stringify(stats ?? item.metadata?.design?.limbs ?? {}, null, 1);
  setDownloads();
}

function renderGallery(viewer, items) {
  gallery = items;
  const host = $('gallery');
  host.replaceChildren();
  host.hidden = items.length < 2;
  items.forEach((item, i) => {
    const button = document.createElement('button');
    button.type = 'button';
    button.textContent = item.name;
    button.setAttribute('aria-pressed', String(i === 0));
    button.addEventListener('click', async () => {
      for (const b of host.children) b.setAttribute('aria-pressed', 'false');
      button.setAttribute('aria-pressed', 'true');
      await show(viewer, item);
    });
    host.append(button);
  });
}

/** Seconds since `start` (performance.now()) as text. */
const since = (start) => `${((performance.now() - start) / 1000).toFixed(2)} s`;

/** POST with the request's round trip recorded in `timing.request`. */
async function timedPost(path, body, timing) {
  const start = performance.now();
  const reply = await post(path, body);
  timing.request = since(start);
  return reply;
}

/** Runs one generation: disables the button, reports the times or the error. */
async function generate(button, work) {
  button.disabled = true;
  setStatus('generating…');
  const start = performance.now();
  const timing = {};
  try {
    const note = await work(timing);
    setStatus(`done in ${since(start)} (request ${timing.request})${note ? ' — ' + note : ''}`);
  } catch (e) {
    setStatus(e instanceof ApiError || e instanceof SyntaxError ? e.message : `error: ${e}`, true);
    throw e;
  } finally {
    button.disabled = false;
  }
}

async function main() {
  const viewer = new Viewer($('canvas-host'));
  window.ramusStudio = { viewer };  // for tests and the console
  const examples = await getExamples();
  const skeleton = new SkeletonPanel(examples);
  const lsystem = new LsystemPanel(examples);
  const colonize = new ColonizePanel(examples);

  for (const tab of document.querySelectorAll('[role="tab"]')) {
    tab.addEventListener('click', () => {
      for (const t of document.querySelectorAll('[role="tab"]')) {
        t.setAttribute('aria-selected', String(t === tab));
        $(`panel-${t.dataset.panel}`).hidden = t !== tab;
      }
    });
  }
  $('opt-wireframe').addEventListener('change', (e) => viewer.setOption('wireframe', e.target.checked));
  $('opt-axes').addEventListener('change', (e) => viewer.setOption('axes', e.target.checked));
  $('opt-grid').addEventListener('change', (e) => viewer.setOption('grid', e.target.checked));
  $('co-show-points').addEventListener('change', (e) => viewer.setPointsVisible(e.target.checked));

  $('panel-skeleton').addEventListener('submit', (event) => {
    event.preventDefault();
    generate($('sk-generate'), async (timing) => {
      const body = await timedPost('/api/skeleton', skeleton.request(), timing);
      const items = body.skeletons.map((s) => ({ name: s.name, glb: decodeBase64(s.glb), metadata: s.metadata }));
      renderGallery(viewer, items);
      await show(viewer, items[0]);
      return `${items.length} skeleton${items.length > 1 ? 's' : ''}`;
    }).catch(() => {});
  });
  $('panel-lsystem').addEventListener('submit', (event) => {
    event.preventDefault();
    lsystem.markError(undefined);
    generate($('ls-generate'), async (timing) => {
      try {
        const body = await timedPost('/api/lsystem', lsystem.request(), timing);
        renderGallery(viewer, []);
        await show(viewer, { name: $('ls-preset').value || 'plant', glb: decodeBase64(body.glb) }, body.stats);
        return [`${body.stats.modules} modules, ${body.stats.triangles} triangles`, ...body.warnings].join('; ');
      } catch (e) {
        if (e instanceof ApiError && e.line) lsystem.markError(e.line, e.column);
        throw e;
      }
    }).catch(() => {});
  });
  $('panel-colonize').addEventListener('submit', (event) => {
    event.preventDefault();
    generate($('co-generate'), async (timing) => {
      const body = await timedPost('/api/colonize', colonize.request(), timing);
      renderGallery(viewer, []);
      await show(viewer, { name: $('co-preset').value || 'tree', glb: decodeBase64(body.glb) }, body.stats);
      viewer.showPoints(body.points, 1, colonize.showPoints());
      return [`${body.stats.nodes} nodes`, ...body.warnings].join('; ');
    }).catch(() => {});
  });

  $('dl-glb').addEventListener('click', () => download(current.glb, `${current.name}.glb`, 'model/gltf-binary'));
  $('dl-obj').addEventListener('click', () => download(viewer.objText(), `${current.name}.obj`, 'text/plain'));
  $('dl-meta').addEventListener('click', () =>
    download(JSON.stringify(current.metadata, null, 2), `${current.name}.json`, 'application/json'));
  $('dl-png').addEventListener('click', async () => download(await viewer.pngBlob(), `${current.name}.png`));
  setStatus('ready');
  document.body.dataset.ready = 'true';
}

main().catch((e) => setStatus(`the studio could not start: ${e.message ?? e}`, true));
