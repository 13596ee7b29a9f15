// mechsim's replay page: plays a scenario report's replay/ folder in 3D (three.js), with
// play/pause/scrub/speed, a follow-the-robot camera and the report's plots linked to the time.
// Test hooks: window.mechsimReplay ({ready, error, duration, frames, setTime(t), time()}).
// URL parameters: follow=0 starts with a fixed camera, t=SECONDS starts at that time, zoom=F
// brings the first camera F times closer (0.3: three times farther).
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { readBytes, readJson, readStatus, readText, reportPath } from './data.js';
import { buildRobot, poseObjects, poseRobot } from './robot.js';
import { buildWorld, buildTraces, csvColumns } from './world.js';
import { buildPlots, updatePlots } from './plots.js';
import { buildLasers, updateLasers } from './lasers.js';

const FORMAT = 'mechsim-replay';
const VERSION = 1;

const hooks = { ready: false, error: null };
window.mechsimReplay = hooks;

function showError(message) {
  hooks.error = message;
  const box = document.getElementById('error');
  box.textContent = message;
  box.hidden = false;
}

async function load() {
  const status = await readStatus();
  if (!status.ok) throw new Error(status.error);
  const manifest = await readJson('replay/manifest.json');
  if (manifest.format !== FORMAT || manifest.version !== VERSION) {
    throw new Error(`replay/manifest.json: format '${manifest.format}' version ${manifest.version}; this page reads '${FORMAT}' version ${VERSION}`);
  }
  const [robotJson, worldJson, poseBytes] = await Promise.all([
    readJson(`replay/${manifest.robot_file}`), readJson(`replay/${manifest.world_file}`),
    readBytes(`replay/${manifest.poses.file}`)]);
  const poses = new Float32Array(poseBytes.buffer.slice(poseBytes.byteOffset, poseBytes.byteOffset + poseBytes.byteLength));
  const stride = manifest.poses.stride;
  const frames = Math.floor(poses.length / stride);
  if (frames !== manifest.frames || frames < 1) {
    throw new Error(`replay/${manifest.poses.file}: ${frames} whole frames, the manifest says ${manifest.frames}`);
  }
  return { manifest, robotJson, worldJson, poses, stride, frames };
}

function frameAt(poses, stride, frames, t) {
  let lo = 0;
  let hi = frames - 1;
  while (lo < hi) {  // the last frame at or before t
    const mid = (lo + hi + 1) >> 1;
    if (poses[mid * stride] <= t + 1e-6) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}

async function main() {
  const data = await load();
  const { manifest, poses, stride, frames } = data;
  document.getElementById('title').textContent =
    `${manifest.scenario} — ${manifest.robot} in ${manifest.world}`;
  const rootIndex = Math.max(0, manifest.links.indexOf(manifest.root_link));
  const t0 = poses[0];
  const t1 = poses[(frames - 1) * stride];

  THREE.Object3D.DEFAULT_UP.set(0, 0, 1);
  const view = document.getElementById('view');
  const renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio);
  view.append(renderer.domElement);
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xdfe7ee);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x6b5a48, 1.1));
  const sun = new THREE.DirectionalLight(0xffffff, 1.6);
  sun.position.set(4, -8, 10);
  scene.add(sun);

  const world = await buildWorld(data.worldJson);
  scene.add(world.group);
  const robot = await buildRobot(data.robotJson, manifest.links);
  scene.add(robot.root);
  const odometry = manifest.odometry
    ? csvColumns(await readText(reportPath(manifest.odometry.file)), manifest.odometry.x, manifest.odometry.y) : [];
  scene.add(buildTraces(poses, stride, frames, rootIndex, manifest.waypoints ?? [], world.heightAt, odometry));
  const lasers = await buildLasers(manifest.lasers ?? []);
  for (const l of lasers) scene.add(l.points);

  const camera = new THREE.PerspectiveCamera(50, 1, 0.02, 2000);
  const controls = new OrbitControls(camera, renderer.domElement);
  const rootAt = (k) => {
    const o = k * stride + 1 + 7 * rootIndex;
    return new THREE.Vector3(poses[o], poses[o + 1], poses[o + 2]);
  };
  // Start looking at the robot's right side from a little ahead and above, at a distance from
  // its size (a rover driving +x crosses the view; an arm reaching forward shows its reach).
  const box = new THREE.Box3();
  poseRobot(robot.groups, poses, stride, 0);
  box.setFromObject(robot.root);
  const size = Math.max(0.5, box.getSize(new THREE.Vector3()).length());
  const start = box.getCenter(new THREE.Vector3());
  controls.target.copy(start);
  const params = new URLSearchParams(window.location.search);
  const zoom = Math.min(20, Math.max(0.05, Number(params.get('zoom') ?? 1) || 1));
  camera.position.copy(start).add(new THREE.Vector3(0.55 * size, -1.25 * size, 0.6 * size).multiplyScalar(1 / zoom));
  controls.update();

  const slider = document.getElementById('time');
  const clock = document.getElementById('clock');
  const playButton = document.getElementById('play');
  const speed = document.getElementById('speed');
  const follow = document.getElementById('follow');
  follow.checked = params.get('follow') !== '0';
  slider.min = t0;
  slider.max = t1;
  slider.step = manifest.rate_hz > 0 ? 1 / manifest.rate_hz : 0.01;

  const plotViews = await buildPlots(document.getElementById('plots'), manifest.plots ?? []);

  let t = Math.min(t1, Math.max(t0, Number(params.get('t') ?? t0) || t0));
  let playing = false;
  let lastFollow = null;
  const show = () => {
    const k = frameAt(poses, stride, frames, t);
    poseRobot(robot.groups, poses, stride, k);
    poseObjects(world.objects, manifest.objects ?? [], manifest.links.length, poses, stride, k);
    updateLasers(lasers, t, poses, stride, k);
    const at = rootAt(k);
    if (follow.checked) {
      if (lastFollow) {
        const delta = at.clone().sub(lastFollow);
        camera.position.add(delta);
        controls.target.add(delta);
      }
      lastFollow = at;
    } else {
      lastFollow = null;
    }
    slider.value = t;
    clock.textContent = `${t.toFixed(2)} / ${t1.toFixed(2)} s`;
    updatePlots(plotViews, t, at.x, at.y);
  };
  const resize = () => {
    const w = view.clientWidth;
    const h = view.clientHeight;
    renderer.setSize(w, h);
    camera.aspect = w / Math.max(1, h);
    camera.updateProjectionMatrix();
  };
  window.addEventListener('resize', resize);
  resize();

  const setPlaying = (on) => {
    playing = on;
    playButton.textContent = on ? 'Pause' : 'Play';
  };
  playButton.addEventListener('click', () => {
    if (!playing && t >= t1) t = t0;
    setPlaying(!playing);
  });
  slider.addEventListener('input', () => {
    t = Number(slider.value);
    show();
  });
  follow.addEventListener('change', show);

  // Render on demand (time moved, camera moved, resized): software WebGL (a browser without a
  // GPU) then spends nothing while the picture stands still.
  let needsRender = true;
  controls.addEventListener('change', () => { needsRender = true; });
  window.addEventListener('resize', () => { needsRender = true; });
  const render = () => {
    renderer.render(scene, camera);
    needsRender = false;
  };
  let lastWall = performance.now();
  const frame = (now) => {
    const dt = (now - lastWall) / 1000;
    lastWall = now;
    if (playing) {
      t = Math.min(t1, t + dt * Number(speed.value));
      if (t >= t1) setPlaying(false);
      show();
      needsRender = true;
    }
    controls.update();
    if (needsRender) render();
    requestAnimationFrame(frame);
  };
  slider.addEventListener('input', () => { needsRender = true; });
  follow.addEventListener('change', () => { needsRender = true; });
  show();
  render();
  requestAnimationFrame(frame);

  Object.assign(hooks, {
    duration: t1 - t0,
    start: t0,
    frames,
    setTime(value) {
      t = Math.min(t1, Math.max(t0, value));
      show();
      render();
    },
    time: () => t,
    setRobotVisible(on) {
      robot.root.visible = on;
      render();
    },
    ready: true,
  });
}

main().catch((e) => showError(`mechsim view: ${e.message}`));
