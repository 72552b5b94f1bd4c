// Draws a fixstep-web Session with three.js: rigid bodies and characters as shaded meshes
// with shadows, the water surface as a shaded height mesh, soft bodies as their edges, fluid
// and particles as points. Reads the session's typed
// arrays (views into wasm memory) once per frame and copies nothing per body.
import * as THREE from 'three';

const PALETTE = [0xe4572e, 0x29335c, 0xf3a712, 0x669bbc, 0xa8c686, 0xc86b98, 0x17bebb,
                 0xffc914, 0x76b041, 0xe85d75];

export class SceneView {
  constructor(session, scene) {
    this.session = session;
    this.scene = scene;
    this.group = new THREE.Group();
    scene.add(this.group);
    this.layout = -1;
    this.bodies = [];
    this.handles = new Uint32Array(0);
    this.buildSoft();
    this.buildCharacters();
    this.buildWater();
    this.fluid = this.points(0x3d8bff, 0.05);
    this.particles = this.points(0xffb347, 0.04);
    this.update();
  }

  dispose() {
    this.scene.remove(this.group);
    this.group.traverse((o) => { o.geometry?.dispose(); o.material?.dispose(); });
  }

  buildSoft() {
    const edges = this.session.softEdges();
    if (edges.length === 0) { this.soft = null; return; }
    const positions = this.session.softPositions();
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(positions.length), 3));
    geometry.setIndex(new THREE.BufferAttribute(edges, 1));
    this.soft = new THREE.LineSegments(geometry, new THREE.LineBasicMaterial({ color: 0xf0d060 }));
    this.soft.frustumCulled = false;
    this.group.add(this.soft);
  }

  // One mesh per character (they never rotate), moved by update().
  buildCharacters() {
    this.characters = [];
    for (let i = 0; i < this.session.characterCount; i++) {
      const body = this.session.characterMesh(i);
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(body.positions, 3));
      geometry.setIndex(new THREE.BufferAttribute(body.indices, 1));
      geometry.computeVertexNormals();
      body.free();
      const material = new THREE.MeshStandardMaterial({ color: i % 2 ? 0x17bebb : 0xffc914, roughness: 0.5 });
      const mesh = new THREE.Mesh(geometry, material);
      mesh.castShadow = true;
      mesh.receiveShadow = true;
      mesh.userData.character = i;
      this.group.add(mesh);
      this.characters.push(mesh);
    }
  }

  // The water surface: one vertex per cell centre, two triangles per square of four
  // neighbouring centres; update() sets the heights.
  buildWater() {
    const grid = this.session.waterGrid();
    if (!grid) { this.water = null; return; }
    const [columns, rows, size, ox, oy, oz] = grid;
    const positions = new Float32Array(columns * rows * 3);
    for (let k = 0; k < rows; k++) {
      for (let i = 0; i < columns; i++) {
        const v = 3 * (i + columns * k);
        positions[v] = ox + (i + 0.5) * size;
        positions[v + 1] = oy;
        positions[v + 2] = oz + (k + 0.5) * size;
      }
    }
    const indices = [];
    for (let k = 0; k + 1 < rows; k++) {
      for (let i = 0; i + 1 < columns; i++) {
        const a = i + columns * k, b = a + 1, c = a + columns, d = c + 1;
        indices.push(a, c, b, b, c, d);
      }
    }
    const geometry = new THREE.BufferGeometry();
    const attribute = new THREE.BufferAttribute(positions, 3);
    attribute.setUsage(THREE.DynamicDrawUsage);
    geometry.setAttribute('position', attribute);
    geometry.setIndex(indices);
    const material = new THREE.MeshStandardMaterial({
      color: 0x2f7fd8, roughness: 0.2, metalness: 0.1, transparent: true, opacity: 0.78,
      side: THREE.DoubleSide,
    });
    this.water = new THREE.Mesh(geometry, material);
    this.water.receiveShadow = true;
    this.water.userData.restLevel = oy;
    this.group.add(this.water);
  }

  points(colour, size) {
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(0), 3));
    const points = new THREE.Points(geometry, new THREE.PointsMaterial({ color: colour, size }));
    points.frustumCulled = false;
    this.group.add(points);
    return points;
  }

  // Copies a view into a points object's position attribute, growing it when needed.
  fill(object, view) {
    let attribute = object.geometry.getAttribute('position');
    if (attribute.array.length < view.length) {
      attribute = new THREE.BufferAttribute(new Float32Array(view.length * 2), 3);
      attribute.setUsage(THREE.DynamicDrawUsage);
      object.geometry.setAttribute('position', attribute);
    }
    attribute.array.set(view);
    attribute.needsUpdate = true;
    object.geometry.setDrawRange(0, view.length / 3);
  }

  rebuildBodies() {
    for (const mesh of this.bodies) {
      this.group.remove(mesh);
      mesh.geometry.dispose();
      mesh.material.dispose();
    }
    this.bodies = [];
    this.handles = this.session.bodyHandles();
    for (let i = 0; i < this.handles.length / 2; i++) {
      const body = this.session.bodyMesh(i);
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(body.positions, 3));
      geometry.setIndex(new THREE.BufferAttribute(body.indices, 1));
      geometry.computeVertexNormals();
      const dynamic = body.kind !== 0;
      const colour = dynamic ? PALETTE[this.handles[2 * i] % PALETTE.length] : 0x8a9099;
      const material = new THREE.MeshStandardMaterial({
        color: colour, flatShading: true, roughness: 0.75, side: THREE.DoubleSide,
      });
      const mesh = new THREE.Mesh(geometry, material);
      mesh.castShadow = dynamic;
      mesh.receiveShadow = true;
      mesh.userData.body = i;
      mesh.userData.dynamic = body.kind === 2;
      body.free();
      this.group.add(mesh);
      this.bodies.push(mesh);
    }
  }

  // Moves everything to the session's current state.
  update() {
    let poses = this.session.bodyPoses();
    if (this.session.bodyLayout !== this.layout) {
      this.layout = this.session.bodyLayout;
      this.rebuildBodies();
      poses = this.session.bodyPoses(); // rebuilding called into wasm: take the view again
    }
    for (let i = 0; i < this.bodies.length; i++) {
      const o = 7 * i;
      const mesh = this.bodies[i];
      mesh.position.set(poses[o], poses[o + 1], poses[o + 2]);
      mesh.quaternion.set(poses[o + 3], poses[o + 4], poses[o + 5], poses[o + 6]);
    }
    const centres = this.session.characterPositions();
    for (let i = 0; i < this.characters.length; i++) {
      this.characters[i].position.set(centres[3 * i], centres[3 * i + 1], centres[3 * i + 2]);
    }
    if (this.water) {
      const heights = this.session.waterHeights();
      const attribute = this.water.geometry.getAttribute('position');
      const level = this.water.userData.restLevel;
      for (let c = 0; c < heights.length; c++) attribute.array[3 * c + 1] = level + heights[c];
      attribute.needsUpdate = true;
      this.water.geometry.computeVertexNormals();
    }
    if (this.soft) {
      const attribute = this.soft.geometry.getAttribute('position');
      attribute.array.set(this.session.softPositions());
      attribute.needsUpdate = true;
    }
    this.fill(this.fluid, this.session.fluidPositions());
    this.fill(this.particles, this.session.particlePositions());
  }

  // The handle (index, generation) of body mesh `mesh`.
  handleOf(mesh) {
    const i = mesh.userData.body;
    return [this.handles[2 * i], this.handles[2 * i + 1]];
  }

  // Bounds of what moves (or of everything but planes, when nothing moves).
  bounds() {
    const box = new THREE.Box3();
    for (const mesh of this.bodies) {
      if (mesh.userData.dynamic) box.expandByObject(mesh);
    }
    for (const mesh of [...this.characters, this.water]) {
      if (mesh) box.expandByObject(mesh);
    }
    for (const o of [this.soft, this.fluid, this.particles]) {
      if (o && o.geometry.drawRange.count !== 0) {
        o.geometry.computeBoundingBox();
        if (!o.geometry.boundingBox.isEmpty()) box.union(o.geometry.boundingBox);
      }
    }
    if (box.isEmpty()) box.set(new THREE.Vector3(-3, 0, -3), new THREE.Vector3(3, 3, 3));
    return box;
  }
}
