// In-page half of tests/studio/three-load.mjs: loads glTF files with three.js's GLTFLoader (the
// studio's three.js) and reports what three.js made of each one; the Node script judges.
//
// window.checkFiles([{ url, png }]) loads the files one after the other (so every console message
// belongs to the file being loaded) and resolves to one result per file:
//   { error, warnings, meshes, triangles, gltfMeshes, skins, skinned, lods, custom, pixels, ms }
// (png: also the rendered canvas as a data URL).
// See three-load.mjs for what is checked.
import * as THREE from 'three';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';

const kWidth = 320;
const kHeight = 240;
const kBackground = [255, 0, 255]; // magenta: no lit material comes out exactly like it

// Every console.warn / console.error (GLTFLoader's own, and three.js's THREE.warn / THREE.error,
// e.g. shader compile errors) is recorded for the file being checked instead of being printed:
// what still reaches the console comes from the browser itself, and three-load.mjs reports it.
let messages = [];
for (const level of ['warn', 'error']) {
  console[level] = (...args) => {
    messages.push(`${level}: ${args.map((a) => (a instanceof Error ? a.message : String(a))).join(' ')}`);
  };
}

const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setPixelRatio(1);
renderer.setSize(kWidth, kHeight, false);
document.body.append(renderer.domElement);
const gl = renderer.getContext();
const stage = new THREE.Scene();
stage.background = new THREE.Color().setRGB(...kBackground.map((c) => c / 255), THREE.SRGBColorSpace);
stage.add(new THREE.HemisphereLight(0xffffff, 0x444444, 2.0));
const sun = new THREE.DirectionalLight(0xffffff, 2.0);
sun.position.set(3, 5, 4);
stage.add(sun);
const camera = new THREE.PerspectiveCamera(40, kWidth / kHeight, 0.01, 1e5);
const kComponents = { SCALAR: 1, VEC2: 2, VEC3: 3, VEC4: 4, MAT2: 4, MAT3: 9, MAT4: 16 };

/** The glTF node index of each three.js object that came from a node. */
function nodeObjects(gltf) {
  const byNode = new Map();
  gltf.scene.traverse((o) => {
    const a = gltf.parser.associations.get(o);
    if (a?.nodes !== undefined) byNode.set(a.nodes, o);
  });
  return byNode;
}

/** The glTF node an object came from: itself or its nearest ancestor that has one. */
function nodeOf(gltf, object) {
  for (let o = object; o; o = o.parent) {
    const a = gltf.parser.associations.get(o);
    if (a?.nodes !== undefined) return a.nodes;
  }
  return undefined;
}

function inspect(gltf, result) {
  const json = gltf.parser.json;
  const problems = result.problems;
  result.gltfMeshes = json.meshes?.length ?? 0;

  // Meshes, and the custom (application-specific, "_"-prefixed) vertex attributes of each
  // primitive: GLTFLoader keeps them under their lower-cased name.
  const meshes = [];
  gltf.scene.traverse((o) => { if (o.isMesh) meshes.push(o); });
  result.meshes = meshes.length;
  result.custom = { expected: 0, arrived: 0, wind: 0 };
  for (const mesh of meshes) {
    const g = mesh.geometry;
    const count = g.attributes.position?.count ?? 0;
    result.triangles += (g.index ? g.index.count : count) / 3;
    const a = gltf.parser.associations.get(mesh);
    const primitive = json.meshes?.[a?.meshes]?.primitives?.[a?.primitives];
    if (!primitive) continue;
    for (const [name, accessor] of Object.entries(primitive.attributes)) {
      if (!name.startsWith('_')) continue;
      ++result.custom.expected;
      const attribute = g.attributes[name.toLowerCase()];
      const size = kComponents[json.accessors[accessor]?.type];
      if (!attribute) {
        problems.push(`mesh "${mesh.name}": attribute ${name} missing (geometry has ${Object.keys(g.attributes).join(', ')})`);
      } else if (attribute.count !== count || attribute.itemSize !== size) {
        problems.push(`mesh "${mesh.name}": attribute ${name} has ${attribute.count}×${attribute.itemSize}, expected ${count}×${size}`);
      } else {
        ++result.custom.arrived;
        if (name.startsWith('_WIND')) ++result.custom.wind;
      }
    }
  }

  // Skins: every primitive of a mesh on a skinned node is a THREE.SkinnedMesh bound to a
  // THREE.Skeleton with one bone per joint of the node's skin.
  result.skins = json.skins?.length ?? 0;
  result.skinned = { expected: 0, found: 0, joints: {} };
  const skinsUsed = new Set();
  for (const node of json.nodes ?? []) {
    if (node.skin !== undefined && node.mesh !== undefined) {
      result.skinned.expected += json.meshes?.[node.mesh]?.primitives?.length ?? 0;
    }
  }
  for (const mesh of meshes) {
    if (!mesh.isSkinnedMesh) continue;
    ++result.skinned.found;
    const node = nodeOf(gltf, mesh);
    const skinIndex = json.nodes?.[node]?.skin;
    const joints = json.skins?.[skinIndex]?.joints?.length;
    const skeleton = mesh.skeleton;
    if (!(skeleton instanceof THREE.Skeleton)) {
      problems.push(`skinned mesh "${mesh.name}" has no THREE.Skeleton`);
      continue;
    }
    skinsUsed.add(skinIndex);
    const bones = skeleton.bones;
    result.skinned.joints[skinIndex] = bones.length;
    if (joints === undefined) problems.push(`skinned mesh "${mesh.name}": its node ${node} has no skin`);
    else if (bones.length !== joints) problems.push(`skinned mesh "${mesh.name}": ${bones.length} bones, the skin has ${joints} joints`);
    if (!bones.every((b) => b instanceof THREE.Bone)) problems.push(`skinned mesh "${mesh.name}": a skeleton bone is not a THREE.Bone`);
    if (skeleton.boneInverses.length !== bones.length) problems.push(`skinned mesh "${mesh.name}": ${skeleton.boneInverses.length} inverse bind matrices for ${bones.length} bones`);
    const badInverse = skeleton.boneInverses.findIndex((m) => !m.elements.every(Number.isFinite));
    if (badInverse >= 0) problems.push(`skinned mesh "${mesh.name}": inverse bind matrix of bone ${badInverse} is not finite`);
    const { skinIndex: si, skinWeight: sw } = mesh.geometry.attributes;
    if (!si || !sw) {
      problems.push(`skinned mesh "${mesh.name}": no skinIndex/skinWeight attributes`);
    } else {
      let top = 0;
      for (let i = 0; i < si.array.length; ++i) top = Math.max(top, si.array[i]);
      if (top >= bones.length) problems.push(`skinned mesh "${mesh.name}": joint index ${top} ≥ ${bones.length} bones`);
    }
  }
  if (result.skinned.found < result.skinned.expected) {
    problems.push(`${result.skinned.found} THREE.SkinnedMesh for ${result.skinned.expected} skinned primitives`);
  }
  for (let s = 0; s < result.skins; ++s) {
    if (!skinsUsed.has(s)) problems.push(`skin ${s} (${json.skins[s].joints?.length} joints) is bound to no THREE.SkinnedMesh`);
  }

  // Levels of detail: nodes named <name>_LOD<i> with a mesh arrive as objects holding a mesh.
  const byNode = nodeObjects(gltf);
  result.lods = { expected: 0, arrived: 0 };
  (json.nodes ?? []).forEach((node, index) => {
    if (node.mesh === undefined || !/_LOD\d+$/.test(node.name ?? '')) return;
    ++result.lods.expected;
    const object = byNode.get(index);
    let hasMesh = false;
    object?.traverse((o) => { hasMesh ||= o.isMesh; });
    if (hasMesh) ++result.lods.arrived;
    else problems.push(`LOD node "${node.name}" arrived ${object ? 'without a mesh' : 'nowhere in the scene'}`);
  });
}

/** The model fitted into view like the studio's Viewer.frame(); counts non-background pixels. */
function render(model) {
  stage.add(model);
  try {
    return renderStage(model);
  } finally {
    stage.remove(model); // also when rendering throws: the next file gets a clean stage
  }
}

function renderStage(model) {
  model.updateMatrixWorld(true);
  const box = new THREE.Box3().setFromObject(model);
  let pixels = 0;
  if (!box.isEmpty() && Number.isFinite(box.min.x + box.max.x + box.min.y + box.max.y + box.min.z + box.max.z)) {
    const size = box.getSize(new THREE.Vector3());
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(size.length() / 2, 1e-6);
    const distance = radius / Math.sin(THREE.MathUtils.degToRad(camera.fov / 2));
    camera.position.copy(center).add(new THREE.Vector3(0.8, 0.35, 1).normalize().multiplyScalar(distance));
    camera.near = distance / 100;
    camera.far = distance * 100;
    camera.updateProjectionMatrix();
    camera.lookAt(center);
    gl.getError(); // clear
    renderer.render(stage, camera);
    const data = new Uint8Array(kWidth * kHeight * 4);
    gl.readPixels(0, 0, kWidth, kHeight, gl.RGBA, gl.UNSIGNED_BYTE, data);
    const glError = gl.getError();
    if (glError !== gl.NO_ERROR) messages.push(`error: WebGL error 0x${glError.toString(16)} while rendering`);
    for (let i = 0; i < data.length; i += 4) {
      const d = Math.abs(data[i] - kBackground[0]) + Math.abs(data[i + 1] - kBackground[1]) +
                Math.abs(data[i + 2] - kBackground[2]);
      if (d > 48) ++pixels;
    }
  }
  return { pixels, box: box.isEmpty() ? null : [box.min.toArray(), box.max.toArray()] };
}

function dispose(model) {
  model.traverse((o) => {
    o.geometry?.dispose();
    o.skeleton?.dispose();
    for (const m of [o.material ?? []].flat()) {
      for (const v of Object.values(m)) if (v?.isTexture) v.dispose();
      m.dispose();
    }
  });
  renderer.renderLists.dispose();
}

async function checkFile({ url, png }) {
  messages = [];
  const result = { error: null, problems: [], meshes: 0, triangles: 0, pixels: 0 };
  const start = performance.now();
  let gltf = null;
  try {
    gltf = await new GLTFLoader().loadAsync(url);
  } catch (e) {
    result.error = String(e?.message ?? e);
  }
  if (gltf) {
    gltf.scene ??= new THREE.Group(); // a file without scenes
    try {
      inspect(gltf, result);
      Object.assign(result, render(gltf.scene));
      if (png) result.png = renderer.domElement.toDataURL('image/png');
    } catch (e) {
      result.problems.push(`checking the loaded scene threw: ${e?.message ?? e}`);
    }
    try {
      dispose(gltf.scene);
    } catch (e) {
      result.problems.push(`disposing the scene threw: ${e?.message ?? e}`);
    }
  }
  result.warnings = messages;
  result.ms = Math.round(performance.now() - start);
  return result;
}

window.checkFiles = async (items) => {
  const results = [];
  for (const item of items) results.push(await checkFile(item));
  return results;
};
window.startupMessages = () => messages.splice(0);
document.body.dataset.ready = 'true';
