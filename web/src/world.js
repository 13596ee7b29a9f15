// The world of a report's world.json: the ground plane, boxes and the height field, drawn as a
// mesh coloured by height (the colour map below), plus the base's path and the waypoints.
import * as THREE from 'three';
import { readBytes } from './data.js';
import { meshObject } from './robot.js';

// Height colour map, low to high: deep blue-grey, sand, ochre, rust, pale rock.
const STOPS = [
  [0.0, [0.20, 0.28, 0.45]],
  [0.25, [0.55, 0.52, 0.40]],
  [0.5, [0.80, 0.62, 0.35]],
  [0.75, [0.66, 0.36, 0.22]],
  [1.0, [0.93, 0.90, 0.86]],
];

export function heightColour(f) {
  const x = Math.min(1, Math.max(0, f));
  for (let i = 1; i < STOPS.length; i++) {
    if (x <= STOPS[i][0]) {
      const [x0, c0] = STOPS[i - 1];
      const [x1, c1] = STOPS[i];
      const u = (x - x0) / (x1 - x0);
      return [0, 1, 2].map((k) => c0[k] + u * (c1[k] - c0[k]));
    }
  }
  return STOPS[STOPS.length - 1][1];
}

// Terrain height (m) at world (x, y) by bilinear interpolation; null outside the grid.
export function makeHeightAt(field, heights) {
  if (!field) return () => 0;
  return (x, y) => {
    const u = (x + field.size_x / 2) / field.size_x * (field.cols - 1);
    const v = (y + field.size_y / 2) / field.size_y * (field.rows - 1);
    if (u < 0 || v < 0 || u > field.cols - 1 || v > field.rows - 1) return 0;
    const c = Math.min(field.cols - 2, Math.floor(u));
    const r = Math.min(field.rows - 2, Math.floor(v));
    const fu = u - c;
    const fv = v - r;
    const h = (rr, cc) => heights[rr * field.cols + cc];
    return (1 - fv) * ((1 - fu) * h(r, c) + fu * h(r, c + 1)) + fv * ((1 - fu) * h(r + 1, c) + fu * h(r + 1, c + 1));
  };
}

// At most `limit` samples a side are drawn (the physics keeps the full grid).
function terrainMesh(field, heights, limit = 320) {
  const step = Math.max(1, Math.ceil(Math.max(field.rows, field.cols) / limit));
  const cols = Math.floor((field.cols - 1) / step) + 1;
  const rows = Math.floor((field.rows - 1) / step) + 1;
  const positions = new Float32Array(rows * cols * 3);
  const colours = new Float32Array(rows * cols * 3);
  const span = Math.max(1e-6, field.max - field.min);
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < cols; c++) {
      const gr = r * step;
      const gc = c * step;
      const z = heights[gr * field.cols + gc];
      const i = r * cols + c;
      positions[3 * i] = -field.size_x / 2 + gc * field.size_x / (field.cols - 1);
      positions[3 * i + 1] = -field.size_y / 2 + gr * field.size_y / (field.rows - 1);
      positions[3 * i + 2] = z;
      colours.set(heightColour((z - field.min) / span), 3 * i);
    }
  }
  const index = [];
  for (let r = 0; r + 1 < rows; r++) {
    for (let c = 0; c + 1 < cols; c++) {
      const a = r * cols + c;
      index.push(a, a + 1, a + cols, a + 1, a + cols + 1, a + cols);
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
  geometry.setAttribute('color', new THREE.BufferAttribute(colours, 3));
  geometry.setIndex(index);
  geometry.computeVertexNormals();
  return new THREE.Mesh(geometry, new THREE.MeshStandardMaterial({ vertexColors: true, roughness: 0.95 }));
}

// A primitive's geometry from its extents: a box's edges; a cylinder's diameter, diameter and
// length (axis z); a sphere's diameter.
function shapeGeometry(shape) {
  if (shape.shape === 'cylinder') {
    const geometry = new THREE.CylinderGeometry(shape.size[0] / 2, shape.size[0] / 2, shape.size[2], 32);
    geometry.rotateX(Math.PI / 2);  // three.js cylinders run along y, the world's along z
    return geometry;
  }
  if (shape.shape === 'sphere') return new THREE.SphereGeometry(shape.size[0] / 2, 32, 16);
  return new THREE.BoxGeometry(...shape.size);
}

export async function buildWorld(worldJson) {
  const group = new THREE.Group();
  let heightAt = () => 0;
  if (worldJson.ground_plane) {
    const plane = new THREE.Mesh(new THREE.PlaneGeometry(200, 200),
      new THREE.MeshStandardMaterial({ color: 0x9aa0a6, roughness: 1 }));
    group.add(plane);
    const grid = new THREE.GridHelper(200, 200, 0x3d4247, 0x5d6268);
    grid.rotateX(Math.PI / 2);
    grid.position.z = 0.001;
    group.add(grid);
  }
  const field = worldJson.heightfield;
  if (field) {
    const bytes = await readBytes(`replay/${field.file}`);
    const heights = new Float32Array(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength));
    if (heights.length !== field.rows * field.cols) {
      throw new Error(`replay/${field.file}: ${heights.length} heights, world.json says ${field.rows} x ${field.cols}`);
    }
    group.add(terrainMesh(field, heights));
    heightAt = makeHeightAt(field, heights);
  }
  const meshes = new Map();
  const objects = new Map();  // free objects (fixed: false) by name: the replay moves them
  for (const box of worldJson.boxes ?? []) {
    const mat = new THREE.MeshStandardMaterial({ color: box.fixed ? 0x9c7a54 : 0xc9a36b, roughness: 0.8 });
    if (box.shape === 'mesh') {  // a static model's mesh: its file and scale, in the object's frame
      const holder = new THREE.Group();
      holder.add(await meshObject(box, meshes, mat));
      const [w, x, y, z] = box.pose.q;
      holder.position.set(...box.pose.p);
      holder.quaternion.set(x, y, z, w);
      group.add(holder);
      if (!box.fixed) objects.set(box.name, holder);
      continue;
    }
    const mesh = new THREE.Mesh(shapeGeometry(box), mat);
    const [w, x, y, z] = box.pose.q;
    mesh.position.set(...box.pose.p);
    mesh.quaternion.set(x, y, z, w);
    group.add(mesh);
    if (!box.fixed) objects.set(box.name, mesh);
  }
  // The passive models' bodies: their primitive shapes in the body's frame; the replay's frames
  // move each body (the shapes welded to the world, "world", stay).
  for (const body of worldJson.bodies ?? []) {
    const holder = new THREE.Group();
    const mat = new THREE.MeshStandardMaterial({ color: 0x8aa0b8, roughness: 0.7 });
    for (const s of body.shapes) {
      const mesh = new THREE.Mesh(shapeGeometry(s), mat);
      const [w, x, y, z] = s.pose.q;
      mesh.position.set(...s.pose.p);
      mesh.quaternion.set(x, y, z, w);
      holder.add(mesh);
    }
    group.add(holder);
    if (body.name !== 'world') objects.set(body.name, holder);
  }
  return { group, heightAt, objects };
}

// (x, y) columns of a CSV file's text (header row first), as numbers.
export function csvColumns(text, xName, yName) {
  const lines = text.split('\n').filter((l) => l.trim());
  const header = lines[0].split(',');
  const ix = header.indexOf(xName);
  const iy = header.indexOf(yName);
  if (ix < 0 || iy < 0) throw new Error(`no columns ${xName}, ${yName} in the odometry file`);
  return lines.slice(1).map((l) => {
    const cells = l.split(',');
    return [Number(cells[ix]), Number(cells[iy])];
  }).filter(([x, y]) => Number.isFinite(x) && Number.isFinite(y));
}

// The root link's path over the whole run (blue), the odometry's (magenta, dashed, on the
// ground) and the route's waypoints (green).
export function buildTraces(poses, stride, frames, rootIndex, waypoints, heightAt, odometry = []) {
  const group = new THREE.Group();
  const points = new Float32Array(frames * 3);
  for (let k = 0; k < frames; k++) {
    const o = k * stride + 1 + 7 * rootIndex;
    points.set([poses[o], poses[o + 1], poses[o + 2] + 0.02], 3 * k);
  }
  const path = new THREE.BufferGeometry();
  path.setAttribute('position', new THREE.BufferAttribute(points, 3));
  group.add(new THREE.Line(path, new THREE.LineBasicMaterial({ color: 0x0050ff })));
  if (odometry.length > 1) {
    const points = odometry.map(([x, y]) => new THREE.Vector3(x, y, heightAt(x, y) + 0.04));
    group.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(points),
      new THREE.LineDashedMaterial({ color: 0xff00ff, dashSize: 0.15, gapSize: 0.1 })).computeLineDistances());
  }
  if (waypoints.length > 0) {
    const marker = new THREE.SphereGeometry(0.15, 16, 10);
    const green = new THREE.MeshStandardMaterial({ color: 0x00c000 });
    const route = [];
    for (const [x, y] of waypoints) {
      const z = heightAt(x, y) + 0.12;
      const m = new THREE.Mesh(marker, green);
      m.position.set(x, y, z);
      group.add(m);
      route.push(new THREE.Vector3(x, y, z));
    }
    group.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(route),
      new THREE.LineDashedMaterial({ color: 0x00a000, dashSize: 0.3, gapSize: 0.2 })).computeLineDistances());
  }
  return group;
}
