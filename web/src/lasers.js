// Laser scans of the report (sensors/<laser>.csv: t, then the ranges, the vertical axis's rows
// one after the other) drawn as points in the world: each ray from the sensor's pose on its link
// (the link's recorded pose), yaw along the horizontal axis, pitch up along the vertical one.
import * as THREE from 'three';
import { readText, reportPath } from './data.js';

function parseScans(text) {
  const lines = text.split('\n').filter((l) => l.trim());
  return lines.slice(1).map((l) => l.split(',').map(Number));
}

function angles(axis) {
  const step = axis.count > 1 ? (axis.max - axis.min) / (axis.count - 1) : 0;
  return Array.from({ length: axis.count }, (_, i) => axis.min + i * step);
}

export async function buildLasers(lasers) {
  const views = [];
  for (const laser of lasers) {
    const rows = parseScans(await readText(reportPath(laser.file)));
    const yaw = angles(laser.horizontal);
    const pitch = angles(laser.vertical);
    const directions = [];  // in the sensor frame
    for (const p of pitch) for (const y of yaw) directions.push(new THREE.Vector3(Math.cos(p) * Math.cos(y), Math.cos(p) * Math.sin(y), Math.sin(p)));
    const positions = new Float32Array(directions.length * 3);
    const geometry = new THREE.BufferGeometry();
    geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
    const points = new THREE.Points(geometry, new THREE.PointsMaterial({ color: 0xff2020, size: 4, sizeAttenuation: false }));
    points.frustumCulled = false;
    const [w, x, y, z] = laser.origin.q;
    const X_LS = new THREE.Matrix4().compose(new THREE.Vector3(...laser.origin.p), new THREE.Quaternion(x, y, z, w), new THREE.Vector3(1, 1, 1));
    views.push({ laser, rows, directions, positions, geometry, points, X_LS });
  }
  return views;
}

// The scan at or before t (s) of each laser, seen from the laser's link at frame `k` of the poses.
export function updateLasers(views, t, poses, stride, k) {
  const X_WL = new THREE.Matrix4();
  const X_WS = new THREE.Matrix4();
  const point = new THREE.Vector3();
  for (const v of views) {
    let lo = -1;
    let hi = v.rows.length - 1;
    while (lo < hi) {  // the last row at or before t
      const mid = (lo + hi + 1) >> 1;
      if (v.rows[mid][0] <= t + 1e-6) lo = mid;
      else hi = mid - 1;
    }
    const o = k * stride + 1 + 7 * v.laser.link;
    X_WL.compose(new THREE.Vector3(poses[o], poses[o + 1], poses[o + 2]),
      new THREE.Quaternion(poses[o + 4], poses[o + 5], poses[o + 6], poses[o + 3]), new THREE.Vector3(1, 1, 1));
    X_WS.multiplyMatrices(X_WL, v.X_LS);
    let n = 0;
    const row = lo >= 0 ? v.rows[lo] : [];
    for (let i = 0; i < v.directions.length && lo >= 0; i++) {
      const r = row[i + 1];
      if (!Number.isFinite(r) || r <= v.laser.range_min || r >= v.laser.range_max) continue;
      point.copy(v.directions[i]).multiplyScalar(r).applyMatrix4(X_WS);
      v.positions.set([point.x, point.y, point.z], 3 * n);
      n++;
    }
    v.geometry.setDrawRange(0, n);
    v.geometry.attributes.position.needsUpdate = true;
  }
}
