// The replay page of a multicpg run (docs/replay.md): the recording written by
// report/replay/page.cpp, decoded and drawn with three.js. Z is up, as in MuJoCo.
(function() {
'use strict';

const FORMAT = 'multicpg replay';
const VERSION = 1;
// Playing speeds, in times real time (1: one controller step per control_dt of wall time).
const SPEEDS = [0.25, 0.5, 1, 2, 4, 8, 16, 32, 64];
const DEFAULT_SPEED = 4;
// Steps the gait strip shows on each side of the cursor.
const GAIT_HALF_WINDOW = 150;
// Lines drawn on the ground sit this far above it, so the ground does not hide them (m).
const LINE_LIFT = 0.003;
// An infinite MuJoCo plane (size 0) is drawn as far around the run as the recording's ground
// (data.ground_margin_m). Its texture, and a heightfield's, repeats texrepeat times per this
// many metres (a display choice: checker cells of 12.5 cm under the hexapod's texrepeat 10).
const TEXTURE_TILE = 2.5;
// The camera starts behind and above the trunk (m), as the films' camera (report/render.h).
const CAMERA_DISTANCE = 1.5;
const CAMERA_ELEVATION_DEG = 30;
const CAMERA_AZIMUTH_DEG = 45;
// The gait strip's stance and swing.
const STANCE = '#2b3a55';
const SWING = '#dfe6f0';

const MJ = {
  PLANE: 0,
  HFIELD: 1,
  SPHERE: 2,
  CAPSULE: 3,
  ELLIPSOID: 4,
  CYLINDER: 5,
  BOX: 6,
  MESH: 7
};

const $ = (id) => document.getElementById(id);

function fail(text) {
  const m = $('message');
  m.textContent = text;
  m.hidden = false;
  window.multicpgErrors.push(text);
  throw new Error(text);
}

// ---- the recording -------------------------------------------------------------------------

const data = JSON.parse($('multicpg-replay-data').textContent);
if (data.format !== FORMAT || data.version !== VERSION) {
  fail(
      'This page holds a recording of another format or version (' + data.format + ' ' +
      data.version + '); this script reads ' + FORMAT + ' ' + VERSION + '.');
}

function bytesOf(text) {
  const raw = atob(text);
  const out = new Uint8Array(raw.length);
  for (let i = 0; i < raw.length; ++i) out[i] = raw.charCodeAt(i);
  return out;
}

// Little-endian typed arrays from base64 (page.cpp writes them so).
function typedOf(text, Type) {
  const bytes = bytesOf(text);
  return new Type(bytes.buffer, 0, bytes.byteLength / Type.BYTES_PER_ELEMENT);
}

const rows = data.rows;
const bodies = data.bodies;
const nb = bodies.length;
const legs = data.legs;
const values = data.poses.values;

// Poses: [row][body][x y z qw qx qy qz] as floats (metres, unit quaternions). The file holds,
// body by body and value by value, each step's change from the step before as a zigzag LEB128
// integer of the quantum (page.cpp encode_poses).
const poses = new Float32Array(rows * nb * values);
(function decodePoses() {
  const bytes = bytesOf(data.poses.data);
  let at = 0;
  for (let column = 0; column < nb * values; ++column) {
    const unit = column % values < 3 ? data.poses.unit_m : data.poses.unit_quat;
    let value = 0;
    for (let row = 0; row < rows; ++row) {
      let zigzag = 0;
      let scale = 1;
      let byte;
      do {
        byte = bytes[at++];
        zigzag += (byte & 0x7f) * scale;
        scale *= 128;
      } while (byte & 0x80);
      value += zigzag % 2 ? -(zigzag + 1) / 2 : zigzag / 2;
      poses[(row * nb) * values + column] = value * unit;
    }
  }
  if (at !== bytes.length) fail('The recording\'s poses are damaged.');
})();

const contactBytes = bytesOf(data.contacts);
const contactStride = Math.ceil(legs.length / 8);
function contact(row, leg) {
  return (contactBytes[row * contactStride + (leg >> 3)] >> (leg & 7)) & 1;
}

const firstStep = data.first_step;
const lastStep = firstStep + rows - 1;
const rowOf = (step) => Math.max(0, Math.min(rows - 1, Math.round(step - firstStep)));
const bodyIndex = {};
bodies.forEach((b, i) => {
  bodyIndex[b.name] = i;
});
const trunk = data.trunk >= 0 ? data.trunk : 0;

function bodyPositionAt(row, b) {
  const o = (row * nb + b) * values;
  return [poses[o], poses[o + 1], poses[o + 2]];
}

// The latest item of a step-ordered list whose step is at most `step`.
function latest(list, step) {
  let found = null;
  for (const item of list) {
    if (item.step > step) break;
    found = item;
  }
  return found;
}

// ---- the scene -----------------------------------------------------------------------------

const view = $('view');
let renderer;
try {
  // No antialiasing: in a software renderer (Chromium's SwiftShader) it halves the frame rate
  // (docs/benchmarks.md).
  renderer = new THREE.WebGLRenderer({antialias: false});
} catch (e) {
  fail('This browser cannot draw WebGL, which the replay needs: ' + e.message);
}
renderer.setPixelRatio(window.devicePixelRatio || 1);
view.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color(0xcfd8e0);
const camera = new THREE.PerspectiveCamera(45, 1, 0.01, 200);
camera.up.set(0, 0, 1);
scene.add(new THREE.HemisphereLight(0xffffff, 0x556070, 0.65));
const sun = new THREE.DirectionalLight(0xffffff, 0.6);
sun.position.set(0.5, -0.8, 1.5);
scene.add(sun);
scene.add(sun.target);

// The run's extent on the ground: infinite planes are drawn over it.
const extent = {
  minX: Infinity,
  maxX: -Infinity,
  minY: Infinity,
  maxY: -Infinity
};
for (let row = 0; row < rows; ++row) {
  const p = bodyPositionAt(row, trunk);
  extent.minX = Math.min(extent.minX, p[0]);
  extent.maxX = Math.max(extent.maxX, p[0]);
  extent.minY = Math.min(extent.minY, p[1]);
  extent.maxY = Math.max(extent.maxY, p[1]);
}
if (data.tunnel) {
  extent.maxX = Math.max(extent.maxX, data.start.x + data.tunnel.length_m);
  extent.minY = Math.min(extent.minY, data.start.y - data.tunnel.width_m / 2);
  extent.maxY = Math.max(extent.maxY, data.start.y + data.tunnel.width_m / 2);
}

function checkerTexture(checker, repeatX, repeatY) {
  const canvas = document.createElement('canvas');
  canvas.width = 2;
  canvas.height = 2;
  const g = canvas.getContext('2d');
  const css = (c) => 'rgb(' + c.slice(0, 3).map((v) => Math.round(v * 255)).join(',') + ')';
  g.fillStyle = css(checker.first);
  g.fillRect(0, 0, 2, 2);
  g.fillStyle = css(checker.second);
  g.fillRect(1, 0, 1, 1);
  g.fillRect(0, 1, 1, 1);
  const t = new THREE.CanvasTexture(canvas);
  t.magFilter = THREE.NearestFilter;
  t.minFilter = THREE.NearestFilter;
  t.wrapS = THREE.RepeatWrapping;
  t.wrapT = THREE.RepeatWrapping;
  t.repeat.set(repeatX, repeatY);
  return t;
}

// A capsule along z (MuJoCo's): a lathe of two half circles joined by a line.
function capsuleGeometry(radius, half) {
  const points = [];
  const n = 8;
  for (let i = 0; i <= n; ++i) {
    const a = -Math.PI / 2 + (Math.PI / 2) * (i / n);
    points.push(new THREE.Vector2(radius * Math.cos(a), -half + radius * Math.sin(a)));
  }
  for (let i = 0; i <= n; ++i) {
    const a = (Math.PI / 2) * (i / n);
    points.push(new THREE.Vector2(radius * Math.cos(a), half + radius * Math.sin(a)));
  }
  points[0].x = 0;
  points[points.length - 1].x = 0;
  const g = new THREE.LatheBufferGeometry(points, 16);
  g.rotateX(Math.PI / 2);
  return g;
}

// A heightfield's samples: a grid from x[0] to x[1] and y[0] to y[1] in its geom's frame, each
// sample a fraction of the elevation (page.cpp hfield_json).
function hfieldLevels(field) {
  if (!field.decoded) field.decoded = typedOf(field.data, Uint16Array);
  return field.decoded;
}
const hfieldX = (field, c) => field.x[0] + ((field.x[1] - field.x[0]) * c) / (field.ncol - 1);
const hfieldY = (field, r) => field.y[0] + ((field.y[1] - field.y[0]) * r) / (field.nrow - 1);

function hfieldGeometry(field, repeat) {
  const levels = hfieldLevels(field);
  const {nrow, ncol} = field;
  const position = new Float32Array(nrow * ncol * 3);
  const uv = new Float32Array(nrow * ncol * 2);
  for (let r = 0; r < nrow; ++r) {
    for (let c = 0; c < ncol; ++c) {
      const i = r * ncol + c;
      position[3 * i] = hfieldX(field, c);
      position[3 * i + 1] = hfieldY(field, r);
      position[3 * i + 2] = (levels[i] / field.levels) * field.elevation;
      uv[2 * i] = (position[3 * i] * repeat[0]) / TEXTURE_TILE;
      uv[2 * i + 1] = (position[3 * i + 1] * repeat[1]) / TEXTURE_TILE;
    }
  }
  const index = [];
  for (let r = 0; r + 1 < nrow; ++r) {
    for (let c = 0; c + 1 < ncol; ++c) {
      const a = r * ncol + c;
      index.push(a, a + 1, a + ncol, a + 1, a + ncol + 1, a + ncol);
    }
  }
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(position, 3));
  g.setAttribute('uv', new THREE.BufferAttribute(uv, 2));
  g.setIndex(index);
  g.computeVertexNormals();
  return g;
}

function meshGeometry(mesh) {
  const g = new THREE.BufferGeometry();
  g.setAttribute('position', new THREE.BufferAttribute(typedOf(mesh.vertices, Float32Array), 3));
  g.setIndex(Array.from(typedOf(mesh.faces, Int32Array)));
  const flat = g.toNonIndexed();
  flat.computeVertexNormals();
  return flat;
}

// The geometry of a geom of `size` (MuJoCo's meaning per type), and its texture repeat.
function geometryOf(geom, size) {
  switch (geom.type) {
    case MJ.BOX:
      return new THREE.BoxBufferGeometry(2 * size[0], 2 * size[1], 2 * size[2]);
    case MJ.SPHERE:
      return new THREE.SphereBufferGeometry(size[0], 20, 14);
    case MJ.ELLIPSOID: {
      const g = new THREE.SphereBufferGeometry(1, 20, 14);
      g.scale(size[0], size[1], size[2]);
      return g;
    }
    case MJ.CAPSULE:
      return capsuleGeometry(size[0], size[1]);
    case MJ.CYLINDER: {
      const g = new THREE.CylinderBufferGeometry(size[0], size[0], 2 * size[1], 20);
      g.rotateX(Math.PI / 2);
      return g;
    }
    case MJ.PLANE: {
      // An infinite plane (size 0) is drawn over the run's extent around the geom's origin.
      const halfX = size[0] > 0 ?
          size[0] :
          Math.max(Math.abs(extent.minX - geom.pos[0]), Math.abs(extent.maxX - geom.pos[0])) +
              data.ground_margin_m;
      const halfY = size[1] > 0 ?
          size[1] :
          Math.max(Math.abs(extent.minY - geom.pos[1]), Math.abs(extent.maxY - geom.pos[1])) +
              data.ground_margin_m;
      return new THREE.PlaneBufferGeometry(2 * halfX, 2 * halfY);
    }
    case MJ.HFIELD:
      return hfieldGeometry(data.hfields[geom.hfield], geom.checker ? geom.checker.repeat : [1, 1]);
    case MJ.MESH:
      return meshGeometry(data.meshes[geom.mesh]);
    default:
      return null;
  }
}

function materialOf(geom, geometry) {
  const options = {color: new THREE.Color(geom.rgba[0], geom.rgba[1], geom.rgba[2])};
  if (geom.rgba[3] < 1) {
    options.transparent = true;
    options.opacity = geom.rgba[3];
    options.depthWrite = false;
  }
  if (geom.checker && (geom.type === MJ.PLANE || geom.type === MJ.HFIELD || geom.type === MJ.BOX)) {
    let rx = geom.checker.repeat[0];
    let ry = geom.checker.repeat[1];
    if (geom.type === MJ.PLANE) {
      geometry.computeBoundingBox();
      const b = geometry.boundingBox;
      const tile = geom.size[0] > 0 ? 2 * geom.size[0] : TEXTURE_TILE;
      rx *= (b.max.x - b.min.x) / tile;
      ry *= (b.max.y - b.min.y) / (geom.size[1] > 0 ? 2 * geom.size[1] : TEXTURE_TILE);
    } else if (geom.type === MJ.BOX) {
      rx = ry = 1;
    }
    options.map = checkerTexture(geom.checker, rx, ry);
    options.color = new THREE.Color(1, 1, 1);
  }
  if (geom.type === MJ.MESH) options.flatShading = true;
  return new THREE.MeshLambertMaterial(options);
}

// One group per body, placed in the world each step; the world's geoms stand in the scene.
const bodyGroups = bodies.map((b) => {
  const g = new THREE.Group();
  g.name = b.name;
  scene.add(g);
  return g;
});
const geomMeshes = data.geoms.map((geom) => {
  const geometry = geometryOf(geom, geom.size);
  if (!geometry) return null;
  const mesh = new THREE.Mesh(geometry, materialOf(geom, geometry));
  mesh.name = geom.name;
  mesh.position.set(geom.pos[0], geom.pos[1], geom.pos[2]);
  mesh.quaternion.set(geom.quat[1], geom.quat[2], geom.quat[3], geom.quat[0]);
  mesh.userData = {geom, colour: mesh.material.color.clone(), shape: null};
  (geom.body >= 0 ? bodyGroups[geom.body] : scene).add(mesh);
  return mesh;
});
const worldMeshes = geomMeshes.filter((m, i) => m && data.geoms[i].body < 0);
scene.updateMatrixWorld(true);

// The ground's height under (x, y): the highest world geom a vertical ray meets; heightfields
// are read directly (a ray through their many triangles would be slow).
const raycaster = new THREE.Raycaster();
const down = new THREE.Vector3(0, 0, -1);
function groundHeight(x, y) {
  let best = -Infinity;
  raycaster.set(new THREE.Vector3(x, y, 1e3), down);
  const meshes = worldMeshes.filter((m) => m.userData.geom.type !== MJ.HFIELD);
  for (const hit of raycaster.intersectObjects(meshes, false)) best = Math.max(best, hit.point.z);
  data.geoms.forEach((geom) => {
    if (geom.type !== MJ.HFIELD || geom.body >= 0) return;
    const field = data.hfields[geom.hfield];
    const u = ((x - geom.pos[0] - field.x[0]) / (field.x[1] - field.x[0])) * (field.ncol - 1);
    const v = ((y - geom.pos[1] - field.y[0]) / (field.y[1] - field.y[0])) * (field.nrow - 1);
    if (!(u >= 0 && v >= 0 && u <= field.ncol - 1 && v <= field.nrow - 1)) return;
    const levels = hfieldLevels(field);
    const c = Math.min(Math.floor(u), field.ncol - 2);
    const r = Math.min(Math.floor(v), field.nrow - 2);
    const at = (rr, cc) => levels[rr * field.ncol + cc] / field.levels;
    const fu = u - c;
    const fv = v - r;
    const h = (1 - fv) * ((1 - fu) * at(r, c) + fu * at(r, c + 1)) +
        fv * ((1 - fu) * at(r + 1, c) + fu * at(r + 1, c + 1));
    best = Math.max(best, geom.pos[2] + h * field.elevation);
  });
  return best === -Infinity ? 0 : best;
}

// The trunk's path on the ground, and the course: a line from the start along its heading.
(function drawLines() {
  const path = [];
  for (let row = 0; row < rows; ++row) {
    const p = bodyPositionAt(row, trunk);
    const last = path[path.length - 1];
    if (last && Math.hypot(p[0] - last.x, p[1] - last.y) < 0.002 && row !== rows - 1) continue;
    path.push(new THREE.Vector3(p[0], p[1], groundHeight(p[0], p[1]) + LINE_LIFT));
  }
  const pathLine = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(path),
      new THREE.LineBasicMaterial({color: 0x1f5fbf}));
  pathLine.name = 'trunk path';
  scene.add(pathLine);
  const yaw = (data.start.yaw_deg * Math.PI) / 180;
  let length = data.tunnel ? data.tunnel.length_m : 0;
  for (const p of path) {
    length = Math.max(
        length, (p.x - data.start.x) * Math.cos(yaw) + (p.y - data.start.y) * Math.sin(yaw));
  }
  length += 0.5;
  const course = [];
  const samples = 100;
  for (let i = 0; i <= samples; ++i) {
    const x = data.start.x + Math.cos(yaw) * (length * i) / samples;
    const y = data.start.y + Math.sin(yaw) * (length * i) / samples;
    course.push(new THREE.Vector3(x, y, groundHeight(x, y) + LINE_LIFT));
  }
  const courseLine = new THREE.Line(
      new THREE.BufferGeometry().setFromPoints(course),
      new THREE.LineDashedMaterial({color: 0x222222, dashSize: 0.05, gapSize: 0.04}));
  courseLine.computeLineDistances();
  courseLine.name = 'course';
  scene.add(courseLine);
})();

// ---- faults in colour ----------------------------------------------------------------------

let paintShown = undefined;
function showPaint(step) {
  const paint = latest(data.paints, step);
  if (paint === paintShown) return;
  paintShown = paint;
  const colours = {};
  const shapes = {};
  if (paint) {
    paint.colours.forEach((c) => {
      colours[c.geom] = c.rgba;
    });
    paint.reshaped.forEach((s) => {
      shapes[s.geom] = s;
    });
  }
  geomMeshes.forEach((mesh, i) => {
    if (!mesh) return;
    const c = colours[i];
    if (c)
      mesh.material.color.setRGB(c[0], c[1], c[2]);
    else
      mesh.material.color.copy(mesh.userData.colour);
    const shape = shapes[i] || null;
    if (shape !== mesh.userData.shape) {
      const s = shape || mesh.userData.geom;
      mesh.geometry.dispose();
      mesh.geometry = geometryOf(mesh.userData.geom, s.size);
      mesh.position.set(s.pos[0], s.pos[1], s.pos[2]);
      mesh.quaternion.set(s.quat[1], s.quat[2], s.quat[3], s.quat[0]);
      mesh.userData.shape = shape;
    }
  });
}

// ---- the camera ----------------------------------------------------------------------------

const controls = new THREE.OrbitControls(camera, renderer.domElement);
controls.enableDamping = false;
controls.enableKeys = false;  // the arrow keys step through the run
controls.screenSpacePanning = true;
const followBox = $('follow');

function resetView(row) {
  const p = bodyPositionAt(row, trunk);
  const yaw = (data.start.yaw_deg * Math.PI) / 180;
  const az = yaw + Math.PI + (CAMERA_AZIMUTH_DEG * Math.PI) / 180;
  const el = (CAMERA_ELEVATION_DEG * Math.PI) / 180;
  controls.target.set(p[0], p[1], p[2]);
  camera.position.set(
      p[0] + CAMERA_DISTANCE * Math.cos(el) * Math.cos(az),
      p[1] + CAMERA_DISTANCE * Math.cos(el) * Math.sin(az), p[2] + CAMERA_DISTANCE * Math.sin(el));
  controls.update();
}

function resize() {
  const w = view.clientWidth;
  const h = view.clientHeight;
  renderer.setSize(w, h, false);
  camera.aspect = w / Math.max(h, 1);
  camera.updateProjectionMatrix();
  drawGait();
  needsRender = true;
}

// ---- the timeline, the trials and the overlay ---------------------------------------------

const morphLegs = legs;
const events = data.events;
const fmt = (v, d) => Number(v).toFixed(d);
const periodsText = (p) => p.map((v, i) => morphLegs[i] + ' ' + v).join('  ');
function eventText(e) {
  switch (e.kind) {
    case 'fault':
      return (e.fault || e.legs) + ' failed';
    case 'recovery':
      return (e.fault || e.legs) + ' works again';
    case 'detection':
      return 'deviation ' + fmt(e.deviation_deg, 1) +
          ' deg detected: CPGs desynchronised, learning starts';
    case 'trial_start':
      return 'learning: trial ' + e.trial;
    case 'trial_end':
      return 'trial ' + e.trial + ': ' + fmt(e.deviation_deg, 1) + ' deg, ' +
          (e.accepted ? 'kept' : 'rejected');
    case 'episode_end':
      return (e.accepted ? 'walks straight' : 'learning stopped') + ' after ' + e.trial + ' trials';
    default:
      return e.kind;
  }
}

const percent = (step) => (rows > 1 ? ((step - firstStep) / (rows - 1)) * 100 : 0);
const markers = $('markers');
function addMarker(kind, classes, step, endStep, title, fields) {
  const m = document.createElement('div');
  m.className = 'marker ' + classes;
  m.style.left = percent(step) + '%';
  if (endStep !== null) m.style.width = Math.max(0, percent(endStep) - percent(step)) + '%';
  m.title = title;
  m.dataset.kind = kind;
  m.dataset.step = step;
  Object.keys(fields).forEach((k) => {
    m.dataset[k] = fields[k];
  });
  m.addEventListener('click', () => seek(step));
  markers.appendChild(m);
}

// Each trial from its start to the end of its measured window.
const trials = [];
const starts = {};
events.forEach((e) => {
  const key = e.episode + '/' + e.trial;
  if (e.kind === 'trial_start') starts[key] = e;
  if (e.kind === 'trial_end') trials.push({start: starts[key] || e, end: e});
});
events.forEach((e) => {
  const at = 'step ' + e.step + ': ';
  switch (e.kind) {
    case 'fault':
    case 'recovery':
      addMarker(
          e.kind, e.kind, e.step, null, at + eventText(e), {legs: e.legs, fault: e.fault || ''});
      break;
    case 'detection':
      addMarker(
          e.kind, e.kind, e.step, null, at + eventText(e),
          {episode: e.episode, deviation: e.deviation_deg});
      break;
    case 'trial_end': {
      const start = starts[e.episode + '/' + e.trial] || e;
      addMarker(
          e.kind, 'trial ' + (e.accepted ? 'kept' : 'rejected'), start.step, e.step,
          'steps ' + start.step + '-' + e.step + ': episode ' + e.episode + ', trial ' + e.trial +
              ', periods ' + periodsText(e.periods) + ', ' + fmt(e.deviation_deg, 2) + ' deg, ' +
              (e.accepted ? 'kept' : 'rejected'),
          {
            episode: e.episode,
            trial: e.trial,
            periods: e.periods.join(','),
            deviation: e.deviation_deg,
            accepted: e.accepted,
            start: start.step
          });
      break;
    }
    case 'episode_end':
      addMarker(
          e.kind, 'episode_end ' + (e.accepted ? 'held' : 'not-held'), e.step, null,
          at + eventText(e) + ', periods ' + periodsText(e.periods) + ', ' +
              fmt(e.deviation_deg, 2) + ' deg',
          {
            episode: e.episode,
            trial: e.trial,
            periods: e.periods.join(','),
            deviation: e.deviation_deg,
            accepted: e.accepted
          });
      break;
    default:
      break;
  }
});

// The failed legs at the end, for the trials' table.
function failedLegsAt(step) {
  const failed = new Set();
  events.forEach((e) => {
    if (e.step > step || (e.kind !== 'fault' && e.kind !== 'recovery') || !e.fault) return;
    if (e.fault.indexOf(':') >= 0 || e.fault.indexOf('.') >= 0) return;  // not a whole leg
    e.legs.split('+').forEach((leg) => {
      if (e.kind === 'fault')
        failed.add(leg);
      else
        failed.delete(leg);
    });
  });
  return failed;
}

const trialRows = [];
(function trialsTable() {
  if (trials.length === 0) return;
  $('trials-section').hidden = false;
  const table = $('trials');
  // A model-based learner's forecast of each trial's E: median and band (docs/learning.md
  // "Inside the model").
  const predicted = trials.some((t) => 'predicted_e_deg' in t.end);
  const head = document.createElement('tr');
  const numeric = ['deviation (deg)'].concat(predicted ? ['predicted (deg) [band]'] : []);
  ['episode', 'trial']
      .concat(morphLegs, numeric, ['decision', 'steps'])
      .forEach((t, i) => {
        const th = document.createElement('th');
        th.textContent = t;
        if (i >= morphLegs.length + 2 + numeric.length) th.className = 'left';
        head.appendChild(th);
      });
  table.appendChild(head);
  trials.forEach((t) => {
    const failed = failedLegsAt(t.start.step);
    const tr = document.createElement('tr');
    const cell = (text, cls) => {
      const td = document.createElement('td');
      td.textContent = text;
      if (cls) td.className = cls;
      tr.appendChild(td);
      return td;
    };
    cell(t.end.episode);
    cell(t.end.trial);
    t.end.periods.forEach(
        (p, i) => cell(
            failed.has(morphLegs[i]) ? p + ' \u00d7' : p,
            failed.has(morphLegs[i]) ? 'disabled' : ''));
    cell(fmt(t.end.deviation_deg, 2));
    if (predicted) {
      cell('predicted_e_deg' in t.end ?
               fmt(t.end.predicted_e_deg, 2) + ' [' + fmt(t.end.predicted_e_low_deg, 2) + ', ' +
                   fmt(t.end.predicted_e_high_deg, 2) + ']' :
               '');
    }
    cell(t.end.accepted ? 'kept' : 'rejected', 'left');
    const link = document.createElement('a');
    link.href = '#step=' + t.start.step;
    link.textContent = t.start.step + '\u2013' + t.end.step;
    link.className = 'trial-link';
    link.addEventListener('click', (ev) => {
      ev.preventDefault();
      seek(t.start.step);
    });
    cell('', 'left').appendChild(link);
    trialRows.push({tr, trial: t});
    table.appendChild(tr);
  });
})();

(function legend() {
  const items = [
    ['fault', '#d21414'], ['recovery', '#2a9a2a'],
    ['deviation detected (CPGs desynchronised)', '#e07b00'], ['trial kept', '#4c9a2a'],
    ['trial rejected', '#b9b9b9'], ['held', '#127512'], ['stance', STANCE], ['swing', SWING],
    ['trunk path', '#1f5fbf'], ['course', '#222']
  ];
  const l = $('legend');
  items.forEach(([name, colour]) => {
    const s = document.createElement('span');
    s.style.background = colour;
    l.appendChild(s);
    l.appendChild(document.createTextNode(name));
  });
})();

(function summary() {
  const faults =
      events.filter((e) => e.kind === 'fault').map((e) => (e.fault || e.legs) + '@' + e.step);
  const dt = data.control_dt;
  $('summary').textContent = data.robot + ', steps ' + firstStep + '\u2013' + lastStep + ' (' +
      fmt(rows * dt, 1) + ' s at ' + fmt(1 / dt, 0) + ' Hz), faults ' +
      (faults.length ? faults.join(', ') : 'none') +
      (trials.length ? ', ' + trials.length + ' trials' : '');
})();

function captionAt(step) {
  const e = latest(events, step);
  return e ? eventText(e) : 'walking';
}

// ---- the gait strip ------------------------------------------------------------------------

const gait = $('gait');
function drawGait() {
  const w = gait.clientWidth;
  const h = gait.clientHeight;
  if (gait.width !== w) gait.width = w;
  if (gait.height !== h) gait.height = h;
  const g = gait.getContext('2d');
  g.clearRect(0, 0, w, h);
  const label = 34;
  const lane = h / legs.length;
  const from = current - GAIT_HALF_WINDOW;
  const span = 2 * GAIT_HALF_WINDOW + 1;
  const px = (w - label) / span;
  const paint = latest(data.paints, current);
  const failedColour = paint ? paint.legs : {};
  g.font = '11px sans-serif';
  g.textBaseline = 'middle';
  for (let leg = 0; leg < legs.length; ++leg) {
    const y = leg * lane;
    const c = failedColour[legs[leg]];
    g.fillStyle =
        c ? 'rgb(' + c.slice(0, 3).map((v) => Math.round(v * 255)).join(',') + ')' : '#222';
    g.fillText(legs[leg], 4, y + lane / 2);
    // One rectangle per stance or swing phase.
    const first = Math.max(from, firstStep);
    const last = Math.min(from + span - 1, lastStep);
    for (let start = first; start <= last;) {
      const phase = contact(start - firstStep, leg);
      let end = start;
      while (end + 1 <= last && contact(end + 1 - firstStep, leg) === phase) ++end;
      g.fillStyle = phase ? STANCE : SWING;
      g.fillRect(label + (start - from) * px, y + 1, (end - start + 1) * px, lane - 2);
      start = end + 1;
    }
  }
  g.strokeStyle = '#d21414';
  g.lineWidth = 2;
  const x = label + (current - from + 0.5) * px;
  g.beginPath();
  g.moveTo(x, 0);
  g.lineTo(x, h);
  g.stroke();
}

// ---- playing -------------------------------------------------------------------------------

let current = firstStep;
let playing = false;
let speed = DEFAULT_SPEED;
let needsRender = true;
let lastFrame = null;
let position = firstStep;  // fractional while playing
const scrubber = $('scrubber');
scrubber.min = firstStep;
scrubber.max = lastStep;
const stepInput = $('step');
stepInput.min = firstStep;
stepInput.max = lastStep;
const speedSelect = $('speed');
SPEEDS.forEach((s) => {
  const o = document.createElement('option');
  o.value = s;
  o.textContent = s + '\u00d7';
  if (s === DEFAULT_SPEED) o.selected = true;
  speedSelect.appendChild(o);
});

function placeBodies(row) {
  for (let b = 0; b < nb; ++b) {
    const o = (row * nb + b) * values;
    const g = bodyGroups[b];
    g.position.set(poses[o], poses[o + 1], poses[o + 2]);
    g.quaternion.set(poses[o + 4], poses[o + 5], poses[o + 6], poses[o + 3]).normalize();
  }
}

function show(step) {
  const before = bodyPositionAt(rowOf(current), trunk);
  current = Math.max(firstStep, Math.min(lastStep, Math.round(step)));
  const row = rowOf(current);
  placeBodies(row);
  showPaint(current);
  if (followBox.checked) {
    const p = bodyPositionAt(row, trunk);
    const d = new THREE.Vector3(p[0] - before[0], p[1] - before[1], p[2] - before[2]);
    camera.position.add(d);
    controls.target.add(d);
    controls.update();
  }
  scrubber.value = current;
  if (document.activeElement !== stepInput) stepInput.value = current;
  $('time').textContent = fmt(current * data.control_dt, 2) + ' s';
  const periods = latest(data.periods, current);
  const paint = latest(data.paints, current);
  $('overlay').textContent = 'Step     ' + current + '\nTime     ' +
      fmt(current * data.control_dt, 1) + ' s\nPeriods  ' +
      (periods ? periodsText(periods.periods) : '') + '\nFaults   ' +
      (paint ? paint.faults : 'none') + '\n' + captionAt(current);
  trialRows.forEach(({tr, trial}) => {
    tr.classList.toggle('current', current >= trial.start.step && current <= trial.end.step);
  });
  drawGait();
  needsRender = true;
}

function seek(step) {
  position = step;
  show(step);
}

function setPlaying(on) {
  playing = on;
  if (playing && current >= lastStep) seek(firstStep);
  lastFrame = null;
  $('play').innerHTML = playing ? '&#10074;&#10074;' : '&#9654;';
}

$('play').addEventListener('click', () => setPlaying(!playing));
$('back').addEventListener('click', () => seek(current - 1));
$('forward').addEventListener('click', () => seek(current + 1));
$('reset').addEventListener('click', () => {
  resetView(rowOf(current));
  needsRender = true;
});
speedSelect.addEventListener('change', () => {
  speed = Number(speedSelect.value);
});
scrubber.addEventListener('input', () => seek(Number(scrubber.value)));
stepInput.addEventListener('change', () => seek(Number(stepInput.value)));
controls.addEventListener('change', () => {
  needsRender = true;
});
window.addEventListener('resize', resize);
document.addEventListener('keydown', (e) => {
  if (e.target === stepInput) return;
  if (e.key === ' ') {
    setPlaying(!playing);
    e.preventDefault();
  }
  if (e.key === 'ArrowLeft') seek(current - 1);
  if (e.key === 'ArrowRight') seek(current + 1);
});
function fromHash() {
  const m = /step=(-?\d+)/.exec(location.hash);
  if (m) seek(Number(m[1]));
}
window.addEventListener('hashchange', fromHash);

// Frames drawn, for measureFps, which draws every frame while it measures.
let frames = 0;
let measuring = false;
function frame(now) {
  if (measuring) needsRender = true;
  if (playing) {
    if (lastFrame !== null) {
      position += (speed * (now - lastFrame)) / 1000 / data.control_dt;
      if (position >= lastStep) {
        position = lastStep;
        setPlaying(false);
      }
      if (Math.round(position) !== current) show(position);
    }
    lastFrame = now;
  }
  if (needsRender) {
    renderer.render(scene, camera);
    needsRender = false;
    ++frames;
  }
  requestAnimationFrame(frame);
}

resetView(0);
seek(firstStep);
fromHash();
resize();
requestAnimationFrame(frame);

// What tests and scripts read of the page (docs/replay.md "Checking a replay").
window.multicpgReplay = {
  format: FORMAT,
  version: VERSION,
  firstStep,
  lastStep,
  bodies: () => bodies.map((b) => b.name),
  // The position (m) the page shows for body `name` at `step`: it moves there and reads the
  // body's place in the drawn scene.
  bodyPosition(step, name) {
    if (!(name in bodyIndex)) throw new Error('no body named ' + name);
    seek(step);
    const p = bodyGroups[bodyIndex[name]].position;
    return [p.x, p.y, p.z];
  },
  // The timeline's markers as the page drew them.
  events: () => Array.from(markers.children).map((m) => Object.assign({}, m.dataset)),
  // Each trial's steps and its row's cells as the table shows them.
  trials: () => trialRows.map(({tr, trial}) => ({
                                start: trial.start.step,
                                end: trial.end.step,
                                cells: Array.from(tr.children).map((td) => td.textContent),
                              })),
  trialHeader: () =>
      Array.from($('trials').querySelector('tr').children).map((th) => th.textContent),
  contact: (step, leg) => contact(rowOf(step), legs.indexOf(leg)),
  seek,
  currentStep: () => current,
  play: () => setPlaying(true),
  pause: () => setPlaying(false),
  setSpeed(s) { speed = s; },
  render() { renderer.render(scene, camera); },
  // Plays for `ms` of real time and resolves to the frames drawn per second.
  measureFps(ms) {
    return new Promise((resolve) => {
      const startFrames = frames;
      const start = performance.now();
      measuring = true;
      setPlaying(true);
      setTimeout(() => {
        measuring = false;
        setPlaying(false);
        resolve(((frames - startFrames) * 1000) / (performance.now() - start));
      }, ms);
    });
  },
};
document.body.dataset.replay = 'ready';
})();
