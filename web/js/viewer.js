// The 3D view: orbit controls, ground grid, wireframe and bone-axes toggles, bone highlight.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { GLTFLoader } from 'three/addons/loaders/GLTFLoader.js';
import { OBJExporter } from 'three/addons/exporters/OBJExporter.js';

const kHighlight = new THREE.Color(0xe0a64a);
const kPlain = new THREE.Color(0xffffff);

export class Viewer {
  constructor(host) {
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    host.append(this.renderer.domElement);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0x2b2f33);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 1e5);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x444444, 2.0));
    const sun = new THREE.DirectionalLight(0xffffff, 2.0);
    sun.position.set(3, 5, 4);
    this.scene.add(sun);
    this.grid = new THREE.GridHelper(10, 20, 0x666666, 0x444444);
    this.scene.add(this.grid);
    this.model = null;
    this.points = null;
    this.axes = [];
    this.options = { wireframe: false, axes: false, grid: true };
    this.host = host;
    new ResizeObserver(() => this.resize()).observe(host);
    this.resize();
    // Render on demand (a change of view or model), not every frame: idle pages cost nothing.
    this.controls.addEventListener('change', () => this.requestRender());
    this.renderPending = false;
  }

  requestRender() {
    if (this.renderPending) return;
    this.renderPending = true;
    requestAnimationFrame(() => {
      this.renderPending = false;
      this.renderer.render(this.scene, this.camera);
    });
  }

  resize() {
    const { clientWidth: w, clientHeight: h } = this.host;
    if (w === 0 || h === 0) return;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.requestRender();
  }

  /** Shows a GLB (ArrayBuffer); resolves to the glTF scene. */
  async show(glb, { frame = true } = {}) {
    const gltf = await new GLTFLoader().parseAsync(glb, '');
    this.clear();
    this.model = gltf.scene;
    this.scene.add(this.model);
    this.prepareHighlight();
    this.applyOptions();
    if (frame) this.frame();
    return gltf.scene;
  }

  clear() {
    if (this.model) this.scene.remove(this.model);
    if (this.points) this.scene.remove(this.points);
    for (const a of this.axes) a.parent?.remove(a);
    this.model = null;
    this.points = null;
    this.axes = [];
  }

  /** Attraction points as a flat [x, y, z, …] list in model units (metres after scale). */
  showPoints(flat, scale, visible) {
    if (this.points) this.scene.remove(this.points);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.Float32BufferAttribute(flat.map((v) => v * scale), 3));
    this.points = new THREE.Points(geometry, new THREE.PointsMaterial({ color: 0x7fd17f, size: 2, sizeAttenuation: false }));
    this.points.visible = visible;
    this.scene.add(this.points);
    this.requestRender();
  }

  setPointsVisible(visible) {
    if (this.points) this.points.visible = visible;
    this.requestRender();
  }

  /** Camera and grid fitted to the model. */
  frame() {
    const box = new THREE.Box3().setFromObject(this.model);
    if (box.isEmpty()) return;
    const size = box.getSize(new THREE.Vector3());
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(size.length() / 2, 1e-3);
    const distance = radius / Math.sin(THREE.MathUtils.degToRad(this.camera.fov / 2));
    this.camera.position.copy(center).add(new THREE.Vector3(0.8, 0.35, 1).normalize().multiplyScalar(distance));
    this.camera.near = distance / 100;
    this.camera.far = distance * 100;
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(center);
    this.controls.update();
    const extent = Math.max(size.x, size.z) * 2;
    const cell = 10 ** Math.floor(Math.log10(Math.max(extent, 1e-3) / 4));
    const divisions = Math.min(200, Math.ceil(extent / cell));
    this.scene.remove(this.grid);
    this.grid = new THREE.GridHelper(divisions * cell, divisions, 0x666666, 0x444444);
    this.grid.position.set(center.x, 0, center.z);
    this.scene.add(this.grid);
    this.applyOptions();
  }

  setOption(name, value) {
    this.options[name] = value;
    this.applyOptions();
  }

  applyOptions() {
    this.requestRender();
    this.grid.visible = this.options.grid;
    if (!this.model) return;
    this.model.traverse((o) => {
      if (o.isMesh) for (const m of [o.material].flat()) m.wireframe = this.options.wireframe;
    });
    for (const a of this.axes) a.parent?.remove(a);
    this.axes = [];
    if (this.options.axes) {
      const size = new THREE.Box3().setFromObject(this.model).getSize(new THREE.Vector3()).length() * 0.03;
      this.model.traverse((o) => {
        if (o.isBone) {
          const axes = new THREE.AxesHelper(size);
          axes.material.depthTest = false;
          axes.renderOrder = 1;
          o.add(axes);
          this.axes.push(axes);
        }
      });
    }
  }

  /** Vertex colours so one bone's vertices can be highlighted (rigid skinning: skinIndex.x). */
  prepareHighlight() {
    this.model.traverse((o) => {
      if (!o.isSkinnedMesh) return;
      const count = o.geometry.attributes.position.count;
      o.geometry.setAttribute('color', new THREE.Float32BufferAttribute(new Float32Array(count * 3).fill(1), 3));
      for (const m of [o.material].flat()) m.vertexColors = true;
    });
  }

  /** Highlights the bone `bone` (an Object3D of the shown scene); null clears. */
  highlight(bone) {
    this.model?.traverse((o) => {
      if (!o.isSkinnedMesh) return;
      const joint = bone ? o.skeleton.bones.indexOf(bone) : -1;
      const skin = o.geometry.attributes.skinIndex;
      const color = o.geometry.attributes.color;
      for (let i = 0; i < color.count; ++i) {
        const c = skin.getX(i) === joint ? kHighlight : kPlain;
        color.setXYZ(i, c.r, c.g, c.b);
      }
      color.needsUpdate = true;
    });
    this.requestRender();
  }

  /** The shown model as OBJ text (three.js exporter, world coordinates). */
  objText() {
    return this.model ? new OBJExporter().parse(this.model) : '';
  }

  /** A PNG of the current view. */
  pngBlob() {
    this.renderer.render(this.scene, this.camera);
    return new Promise((resolve) => this.renderer.domElement.toBlob(resolve, 'image/png'));
  }
}
