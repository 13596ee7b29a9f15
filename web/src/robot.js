// The robot as three.js objects from the report's robot.json (the links' visuals as the URDF
// gives them, meshes converted to STL/OBJ by mechsim): one group per link, placed each frame at
// the link's recorded world pose.
import * as THREE from 'three';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { readBytes } from './data.js';

function material(rgba) {
  const [r, g, b, a] = rgba ?? [0.6, 0.6, 0.6, 1];
  return new THREE.MeshStandardMaterial({
    color: new THREE.Color(r, g, b), transparent: a < 1, opacity: a, metalness: 0.1, roughness: 0.7,
  });
}

function applyOrigin(object, origin) {
  const [x, y, z] = origin.p;
  const [w, qx, qy, qz] = origin.q;
  object.position.set(x, y, z);
  object.quaternion.set(qx, qy, qz, w);
}

// A mesh file under replay/ (`visual.file`, STL or OBJ, `visual.scale`), loaded once per cache.
export async function meshObject(visual, cache, mat) {
  if (!cache.has(visual.file)) {
    cache.set(visual.file, readBytes(`replay/${visual.file}`).then((bytes) => {
      if (visual.file.endsWith('.obj')) return { obj: new OBJLoader().parse(new TextDecoder().decode(bytes)) };
      return { geometry: new STLLoader().parse(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength)) };
    }));
  }
  const loaded = await cache.get(visual.file);
  let object;
  if (loaded.geometry) {
    object = new THREE.Mesh(loaded.geometry, mat);
  } else {
    object = loaded.obj.clone();
    object.traverse((child) => { if (child.isMesh) child.material = mat; });
  }
  const [sx, sy, sz] = visual.scale ?? [1, 1, 1];
  object.scale.set(sx, sy, sz);
  return object;
}

async function visualObject(visual, cache) {
  const mat = material(visual.rgba);
  let object;
  switch (visual.type) {
    case 'box':
      object = new THREE.Mesh(new THREE.BoxGeometry(...visual.size), mat);
      break;
    case 'cylinder': {
      const geometry = new THREE.CylinderGeometry(visual.radius, visual.radius, visual.length, 28);
      geometry.rotateX(Math.PI / 2);  // three.js cylinders run along y, URDF's along z
      object = new THREE.Mesh(geometry, mat);
      break;
    }
    case 'sphere':
      object = new THREE.Mesh(new THREE.SphereGeometry(visual.radius, 24, 16), mat);
      break;
    case 'mesh':
      object = await meshObject(visual, cache, mat);
      break;
    default:
      throw new Error(`robot.json: unknown visual type '${visual.type}'`);
  }
  const holder = new THREE.Group();
  holder.add(object);
  applyOrigin(holder, visual.origin);
  return holder;
}

// Groups in the order of manifest.links (the order of the poses in each frame).
export async function buildRobot(robotJson, linkNames) {
  const byName = new Map(robotJson.links.map((l) => [l.name, l]));
  const cache = new Map();
  const root = new THREE.Group();
  const groups = [];
  for (const name of linkNames) {
    const group = new THREE.Group();
    group.name = name;
    const link = byName.get(name);
    for (const visual of link?.visuals ?? []) group.add(await visualObject(visual, cache));
    root.add(group);
    groups.push(group);
  }
  return { root, groups };
}

// Places each link group at frame `k` of the poses (Float32Array, `stride` floats a frame).
// The world's free objects (manifest.objects, after the links in each frame) at frame k.
export function poseObjects(objects, names, linkCount, poses, stride, k) {
  for (let i = 0; i < names.length; i++) {
    const object = objects.get(names[i]);
    if (!object) continue;
    const o = k * stride + 1 + 7 * (linkCount + i);
    object.position.set(poses[o], poses[o + 1], poses[o + 2]);
    object.quaternion.set(poses[o + 4], poses[o + 5], poses[o + 6], poses[o + 3]);
  }
}

export function poseRobot(groups, poses, stride, k) {
  const base = k * stride + 1;
  for (let i = 0; i < groups.length; i++) {
    const o = base + 7 * i;
    groups[i].position.set(poses[o], poses[o + 1], poses[o + 2]);
    groups[i].quaternion.set(poses[o + 4], poses[o + 5], poses[o + 6], poses[o + 3]);
  }
}
