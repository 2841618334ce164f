// urdfsnap serve's page: joint sliders with joint_state_publisher_gui's rules, RViz's orbit
// camera on the mouse, display toggles, and frames fetched from /render.png in `urdfsnap render`'s
// option words, at most one request in flight (the newest state wins; states the renderer had no
// time for are never asked for). The model's reloads are noticed by polling /api/status.
'use strict';

// RViz's orbit camera (rviz/default_plugin/view_controllers/orbit_view_controller.cpp)
const PITCH_LIMIT = Math.PI / 2 - 0.001;  // the Pitch property's range
const ROTATE_PER_PIXEL = 0.005;           // yaw and pitch per pixel dragged
const ZOOM_PER_PIXEL = 0.01;              // right-drag: distance change per pixel, times distance
const ZOOM_PER_WHEEL_UNIT = 0.001;        // per Qt wheel unit (120 a notch), times distance
const WHEEL_UNITS_PER_PIXEL = 1.2;        // a browser's wheel notch is 100 pixels, Qt's 120 units
const MIN_DISTANCE = 0.01, MAX_DISTANCE = 1e6;  // what `render --distance` accepts
const WINDOW_SIZE = 'window';  // the size option that follows the viewport's size
const SIZES = [WINDOW_SIZE, '640x480', '800x600', '1024x768', '1280x720', '1280x960', '1920x1080'];
const MAX_WINDOW_SIDE = 4096;  // a frame the size of a large window, not of a wall display
const RESIZE_SETTLE_MS = 150;  // a window being resized asks for one frame when it stops
const GROUP_ABOVE = 8;         // more joints than this are grouped by their name's first word
const STATUS_POLL_MS = 1000;

const $ = (id) => document.getElementById(id);

const page = {
  initial: null,      // /api/view: the options and pose urdfsnap serve started with
  robot: null,        // /api/robot
  model: null,        // the model's generation the page shows
  view: null,         // {yaw, pitch, distance, focal: [x, y, z]}
  options: null,      // {size, alpha, background, 'no-grid', tf, collision, 'no-visual'}
  joints: new Map(),  // slider joint name -> value
  modelError: '',
  frameError: '',
  camera: false,      // a calibrated camera is served: the orbit controls are off
  cameraView: '',     // its calibration file and placement, for the status line
};

// Numbers as the page writes them into URLs, joint files and suite cases: at most six decimals,
// never an exponent, so the three say exactly the same thing.
function num(x) {
  const rounded = Number(x.toFixed(6));
  return Object.is(rounded, -0) ? '0' : String(rounded);
}

function clamp(x, low, high) { return Math.min(high, Math.max(low, x)); }

// ---- the view and display options --------------------------------------------------------

function viewFromOptions(options) {
  return {
    yaw: Number(options.yaw),
    pitch: Number(options.pitch),
    distance: Number(options.distance),
    focal: options.focal.split(',').map(Number),
  };
}

// The page starts at the options urdfsnap serve was given, with the frame following the window
// unless --size was given.
function optionsFromInitial(options) {
  const o = {};
  for (const key of ['size', 'alpha', 'background', 'no-grid', 'tf', 'collision', 'no-visual']) o[key] = options[key];
  if (!page.initial.size_given) o.size = WINDOW_SIZE;
  return o;
}

// The pixels a frame has: the size chosen, or the viewport's when it follows the window.
function frameSize() {
  if (page.options.size !== WINDOW_SIZE) return page.options.size;
  const viewport = $('viewport');
  const side = (pixels) => clamp(Math.floor(pixels), 16, MAX_WINDOW_SIDE);
  return `${side(viewport.clientWidth)}x${side(viewport.clientHeight)}`;
}

// The render options the page sets, as key -> text (flags as "true"/"false").
function pageOptions() {
  const v = page.view, o = page.options;
  return {
    size: frameSize(),
    yaw: num(v.yaw),
    pitch: num(v.pitch),
    distance: num(v.distance),
    focal: v.focal.map(num).join(','),
    alpha: num(Number(o.alpha)),
    background: o.background,
    fit: 'false',  // /api/view's view is fitted already
    'no-grid': String(o['no-grid']),
    tf: String(o.tf),
    collision: String(o.collision),
    'no-visual': String(o['no-visual']),
  };
}

function frameQuery() {
  const query = new URLSearchParams(pageOptions());
  if (page.recording) query.set('at', num(Number($('at').value)));
  for (const [name, value] of page.joints) query.set('j.' + name, num(value));
  return query.toString();
}

function showControls() {
  const o = page.options;
  $('grid').checked = !o['no-grid'];
  $('tf').checked = o.tf;
  $('visual').checked = !o['no-visual'];
  $('collision').checked = o.collision;
  $('alpha').value = o.alpha;
  $('background').value = '#' + o.background.split(',').map((c) => Number(c).toString(16).padStart(2, '0')).join('');
  const select = $('size');
  if (![...select.options].some((option) => option.value === o.size)) select.add(new Option(o.size, o.size));
  select.value = o.size;
  select.options[0].textContent = 'fit window';
}

function wireControls() {
  for (const size of SIZES) $('size').add(new Option(size, size));
  const toggles = {grid: ['no-grid', true], tf: ['tf', false], visual: ['no-visual', true], collision: ['collision', false]};
  for (const [id, [key, inverted]] of Object.entries(toggles)) {
    $(id).addEventListener('change', (e) => { page.options[key] = e.target.checked !== inverted; requestFrame(); });
  }
  $('alpha').addEventListener('input', (e) => { page.options.alpha = e.target.value; requestFrame(); });
  $('background').addEventListener('input', (e) => {
    const hex = e.target.value;
    page.options.background = [1, 3, 5].map((i) => parseInt(hex.slice(i, i + 2), 16)).join(',');
    requestFrame();
  });
  $('size').addEventListener('change', (e) => { page.options.size = e.target.value; requestFrame(); });
  $('at').addEventListener('input', (e) => { $('at-value').textContent = num(Number(e.target.value)) + ' s'; requestFrame(); });
  let resizing = null;
  window.addEventListener('resize', () => {
    clearTimeout(resizing);
    resizing = setTimeout(() => { if (page.options.size === WINDOW_SIZE) requestFrame(); }, RESIZE_SETTLE_MS);
  });
  $('joint-filter').addEventListener('input', filterSliders);
  $('reset-view').addEventListener('click', () => {
    page.view = viewFromOptions(page.initial.options);
    page.options = optionsFromInitial(page.initial.options);
    showControls();
    requestFrame();
  });
  $('fit-view').addEventListener('click', fitView);
  $('focus').addEventListener('change', fitView);
  $('save-png').addEventListener('click', savePng);
  $('copy-pose').addEventListener('click', () => copyText(poseYaml(), 'A joint file: urdfsnap render MODEL --joints FILE'));
  $('copy-case').addEventListener('click', () => copyText(suiteCaseYaml(), 'A case for the cases: list of a snapshot suite (urdfsnap snapshot check)'));
  $('centre').addEventListener('click', () => setJoints((joint) => joint.default));
  $('randomize').addEventListener('click', () => setJoints((joint) => joint.lower + Math.random() * (joint.upper - joint.lower)));
}

// ---- the orbit camera, as RViz's Orbit view controller moves it ----------------------------

function cameraAxes(view) {
  const cp = Math.cos(view.pitch);
  const back = [Math.cos(view.yaw) * cp, Math.sin(view.yaw) * cp, Math.sin(view.pitch)];
  // right = forward x Z, up = right x forward (no roll: Z is the fixed yaw axis)
  const right = [-back[1], back[0], 0];
  const norm = Math.hypot(right[0], right[1]) || 1;
  right[0] /= norm; right[1] /= norm;
  const up = [-(right[1] * back[2]), right[0] * back[2], right[1] * back[0] - right[0] * back[1]];
  return {right, up, back};
}

// OrbitViewController::move: the focal point moves by (x, y, z) in the camera's frame.
function moveFocal(x, y, z) {
  const {right, up, back} = cameraAxes(page.view);
  page.view.focal = page.view.focal.map((f, i) => f + right[i] * x + up[i] * y + back[i] * z);
}

function zoom(amount) {
  page.view.distance = clamp(page.view.distance - amount, MIN_DISTANCE, MAX_DISTANCE);
}

function wireOrbit() {
  const viewport = $('viewport');
  let drag = null;
  viewport.addEventListener('contextmenu', (e) => e.preventDefault());
  viewport.addEventListener('pointerdown', (e) => {
    if (page.camera) return;   // a calibrated camera's view does not orbit
    drag = {x: e.clientX, y: e.clientY, button: e.button};
    viewport.setPointerCapture(e.pointerId);
    viewport.classList.add('dragging');
    e.preventDefault();
  });
  const end = () => { drag = null; viewport.classList.remove('dragging'); };
  viewport.addEventListener('pointerup', end);
  viewport.addEventListener('pointercancel', end);
  viewport.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX; drag.y = e.clientY;
    if (dx === 0 && dy === 0) return;
    const v = page.view;
    if (drag.button === 0 && !e.shiftKey) {
      v.yaw = ((v.yaw - dx * ROTATE_PER_PIXEL) % (2 * Math.PI) + 2 * Math.PI) % (2 * Math.PI);
      v.pitch = clamp(v.pitch + dy * ROTATE_PER_PIXEL, -PITCH_LIMIT, PITCH_LIMIT);
    } else if (drag.button === 1 || (drag.button === 0 && e.shiftKey)) {
      // the point under the cursor at the focal distance follows the cursor
      const box = $('frame').getBoundingClientRect();
      const tanY = Math.tan(page.initial.fov / 2);
      const tanX = tanY * box.width / box.height;
      moveFocal(-dx / box.width * v.distance * tanX * 2, dy / box.height * v.distance * tanY * 2, 0);
    } else if (drag.button === 2 && e.shiftKey) {
      moveFocal(0, 0, dy * ZOOM_PER_PIXEL * v.distance);
    } else if (drag.button === 2) {
      zoom(-dy * ZOOM_PER_PIXEL * v.distance);
    }
    requestFrame();
  });
  viewport.addEventListener('wheel', (e) => {
    if (page.camera) return;
    e.preventDefault();
    const pixels = e.deltaY || e.deltaX;  // shift turns the wheel sideways in some browsers
    const units = -pixels * (e.deltaMode === 0 ? WHEEL_UNITS_PER_PIXEL : e.deltaMode === 1 ? 40 : 120);
    if (e.shiftKey) moveFocal(0, 0, -units * ZOOM_PER_WHEEL_UNIT * page.view.distance);
    else zoom(units * ZOOM_PER_WHEEL_UNIT * page.view.distance);
    requestFrame();
  }, {passive: false});
}

// The view the server fits to the robot, or to the link the focus list names, for the frame as
// it is now (pose, displays, size, direction); the camera keeps its yaw and pitch.
async function fitView() {
  const query = new URLSearchParams(frameQuery());
  const link = $('focus').value;
  if (link) query.set('link', link);
  try {
    const response = await fetch('api/fit?' + query.toString(), {cache: 'no-store'});
    const body = await response.json();
    if (!response.ok) {
      page.frameError = body.error;
      showError();
      return;
    }
    page.view = {yaw: body.yaw, pitch: body.pitch, distance: body.distance, focal: body.focal};
    requestFrame();
  } catch (error) {
    page.frameError = 'urdfsnap serve does not answer (' + error.message + ')';
    showError();
  }
}

// The focus list: the whole robot, then each link; the choice is kept across reloads while the
// link exists.
function buildFocusList() {
  const select = $('focus');
  const chosen = select.value;
  while (select.options.length > 1) select.remove(1);
  for (const link of page.robot.links) select.add(new Option(link, link));
  select.value = page.robot.links.includes(chosen) ? chosen : '';
}

// ---- joints ------------------------------------------------------------------------------

function sliderJoints() { return page.robot ? page.robot.joints.filter((joint) => !joint.mimic) : []; }

function buildSliders() {
  const box = $('sliders');
  box.replaceChildren();
  const previous = page.joints;
  page.joints = new Map();
  const joints = sliderJoints();
  if (joints.length === 0) {
    const note = document.createElement('p');
    note.className = 'empty';
    note.textContent = 'This robot has no movable joints.';
    box.append(note);
  }
  const groups = jointGroups(joints);
  for (const joint of joints) {
    const start = previous.get(joint.name) ?? page.initial.joints[joint.name] ?? joint.default;
    page.joints.set(joint.name, clamp(start, joint.lower, joint.upper));
    const row = document.createElement('div');
    row.className = 'joint';
    const name = document.createElement('span');
    name.className = 'name';
    name.textContent = joint.name;
    name.title = `${joint.name} (${joint.type}, ${num(joint.lower)} to ${num(joint.upper)} ${joint.type === 'prismatic' ? 'm' : 'rad'})`;
    const slider = document.createElement('input');
    const field = document.createElement('input');
    for (const input of [slider, field]) {
      input.min = joint.lower;
      input.max = joint.upper;
      input.step = 'any';
      input.dataset.joint = joint.name;
    }
    slider.type = 'range';
    field.type = 'number';
    slider.addEventListener('input', () => setJoint(joint, Number(slider.value), field));
    field.addEventListener('change', () => {
      if (field.value !== '' && Number.isFinite(Number(field.value))) setJoint(joint, Number(field.value), slider);
      showJoint(joint.name, slider, field);
    });
    row.append(name, slider, field);
    (groups.get(joint.name) ?? box).append(row);
    showJoint(joint.name, slider, field);
  }
  filterSliders();
}

// A robot with many joints (a PR2 has dozens) gets its sliders in groups by the first word of
// their names (r_, l_, head_, torso_ ...), each a <details> of two or more joints: joint name ->
// the group's element, for the joints that are in one.
function jointGroups(joints) {
  const groups = new Map();
  if (joints.length <= GROUP_ABOVE) return groups;
  const word = (name) => name.split(/[_\-/]/)[0];
  const count = new Map();
  for (const joint of joints) count.set(word(joint.name), (count.get(word(joint.name)) ?? 0) + 1);
  const made = new Map();
  for (const joint of joints) {
    const key = word(joint.name);
    if (count.get(key) < 2) continue;
    if (!made.has(key)) {
      const details = document.createElement('details');
      details.open = true;
      const summary = document.createElement('summary');
      summary.textContent = `${key} (${count.get(key)})`;
      details.append(summary);
      $('sliders').append(details);
      made.set(key, details);
    }
    groups.set(joint.name, made.get(key));
  }
  return groups;
}

// Shows the sliders whose joint name contains the filter's text (any case), and the groups with
// any of them.
function filterSliders() {
  const text = $('joint-filter').value.trim().toLowerCase();
  for (const row of $('sliders').querySelectorAll('.joint')) {
    row.hidden = text !== '' && !row.querySelector('input').dataset.joint.toLowerCase().includes(text);
  }
  for (const group of $('sliders').querySelectorAll('details')) {
    group.hidden = ![...group.querySelectorAll('.joint')].some((row) => !row.hidden);
  }
}

function showJoint(name, slider, field) {
  const value = page.joints.get(name);
  slider.value = value;
  field.value = num(value);
}

function setJoint(joint, value, other) {
  const clamped = clamp(value, joint.lower, joint.upper);
  page.joints.set(joint.name, clamped);
  if (other.type === 'number') other.value = num(clamped); else other.value = clamped;
  requestFrame();
}

function setJoints(valueOf) {
  for (const joint of sliderJoints()) page.joints.set(joint.name, clamp(valueOf(joint), joint.lower, joint.upper));
  for (const row of $('sliders').querySelectorAll('.joint')) {
    const [slider, field] = row.querySelectorAll('input');
    showJoint(slider.dataset.joint, slider, field);
  }
  requestFrame();
}

// ---- frames: one request in flight, the newest state wins ---------------------------------

const frames = {wanted: null, asked: null, busy: false, url: null, blob: null};

function requestFrame() {
  frames.wanted = frameQuery();
  pump();
}

async function pump() {
  if (frames.busy || frames.wanted === null || frames.wanted === frames.asked) return;
  const query = frames.wanted;
  frames.asked = query;
  frames.busy = true;
  let retryAfter = 0;
  try {
    const response = await fetch('render.png?' + query, {cache: 'no-store'});
    if (response.ok) {
      const blob = await response.blob();
      showFrame(blob);
      page.frameError = '';
      const generation = Number(response.headers.get('X-Urdfsnap-Model'));
      if (generation !== page.model) pollStatus();
    } else if (response.status === 503) {
      frames.asked = null;  // the server is busy: ask again shortly
      retryAfter = 100;
    } else {
      page.frameError = await response.text();
    }
  } catch (error) {
    page.frameError = 'urdfsnap serve does not answer (' + error.message + '); retrying';
    frames.asked = null;
    retryAfter = 1000;
  }
  showError();
  frames.busy = false;
  if (retryAfter) setTimeout(pump, retryAfter); else pump();
}

function showFrame(blob) {
  const old = frames.url;
  frames.blob = blob;
  frames.url = URL.createObjectURL(blob);
  const img = $('frame');
  img.src = frames.url;
  // the old frame's URL goes once the new one is decoded (or superseded by a newer one: then
  // decode() rejects, which is no error of ours)
  const revoke = () => { if (old) URL.revokeObjectURL(old); };
  img.decode().then(revoke, revoke);
  const o = page.options, v = page.view;
  if (!page.camera) {
    $('status').textContent = `yaw ${num(v.yaw)} · pitch ${num(v.pitch)} · distance ${num(v.distance)} · focal ${v.focal.map(num).join(',')} · ${frameSize()}`;
    return;
  }
  // a calibrated camera's frame has the calibration's size, whatever the size selector says
  img.decode().then(() => {
    $('status').textContent = `calibrated camera ${page.cameraView} · ${img.naturalWidth}x${img.naturalHeight}`;
  }, () => {});
}

function showError() {
  const text = page.modelError || page.frameError;
  $('error').hidden = !text;
  $('error').textContent = text;
}

// ---- the model: loaded once, again after every reload the server reports -------------------

async function loadRobot() {
  const response = await fetch('api/robot', {cache: 'no-store'});
  const body = await response.json();
  if (!response.ok) {
    page.modelError = body.error;
    showError();
    return false;
  }
  page.robot = body;
  page.modelError = '';
  $('robot-name').textContent = body.name;
  document.title = body.name + ' · urdfsnap serve';
  buildSliders();
  buildFocusList();
  showError();
  return true;
}

async function pollStatus() {
  try {
    const response = await fetch('api/status', {cache: 'no-store'});
    const status = await response.json();
    if (status.model !== page.model) {
      page.model = status.model;
      if (status.error) {
        page.modelError = status.error;
        showError();
      } else if (await loadRobot()) {
        frames.asked = null;  // the same view of a new model is a new frame
        requestFrame();
      }
    }
  } catch (error) {
    // the frame loop reports a server that does not answer
  }
}

async function pollForever() {
  if (!document.hidden) await pollStatus();
  setTimeout(pollForever, STATUS_POLL_MS);
}

// ---- save and copy -----------------------------------------------------------------------

function savePng() {
  if (!frames.url) return;
  const link = document.createElement('a');
  link.href = frames.url;
  link.download = (page.robot ? page.robot.name : 'robot') + '.png';
  link.click();
}

function yamlString(text) { return JSON.stringify(text); }

function poseYaml() {
  const lines = [`# ${page.robot ? page.robot.name : 'robot'}: joint values in rad or m, from urdfsnap serve`];
  for (const [name, value] of page.joints) lines.push(`${yamlString(name)}: ${num(value)}`);
  return lines.join('\n') + '\n';
}

function yamlMap(object) {
  return '{' + Object.entries(object).map(([key, value]) => `${yamlString(key)}: ${yamlString(String(value))}`).join(', ') + '}';
}

function suiteCaseYaml() {
  const base = page.initial.case;
  const options = {...base.options, ...pageOptions()};
  const lines = ['  # a case of a snapshot suite (urdfsnap snapshot check), made by urdfsnap serve',
    `  - name: ${(page.robot ? page.robot.name : 'robot').replace(/[^A-Za-z0-9_.-]/g, '_')}_view`,
    `    model: ${yamlString(base.model)}`];
  if (Object.keys(base.args).length) lines.push(`    args: ${yamlMap(base.args)}`);
  if (Object.keys(base.packages).length) lines.push(`    packages: ${yamlMap(base.packages)}`);
  if (base['xacro-ns']) lines.push('    xacro-ns: true');
  for (const [key, value] of Object.entries(options)) {
    const flag = value === true || value === 'true' || value === 'false';
    lines.push(`    ${key}: ${flag ? String(value) : yamlString(String(value))}`);
  }
  const joints = [...page.joints].map(([name, value]) => `${yamlString(name)}: ${num(value)}`);
  if (joints.length) lines.push(`    joints: {${joints.join(', ')}}`);
  return lines.join('\n') + '\n';
}

async function copyText(text, note) {
  $('copy-text').value = text;
  let copied = false;
  try {
    await navigator.clipboard.writeText(text);
    copied = true;
  } catch (error) {
    // no clipboard outside a secure context (http:// to another host): select it for the user
  }
  $('copy-note').textContent = note + (copied ? ' — copied to the clipboard.' : ' — select it and copy.');
  $('copy-dialog').showModal();
  $('copy-text').select();
}

// ---- start -------------------------------------------------------------------------------

// /api/view, once /api/status says the model has loaded (a model broken at start-up is served as
// its error until an edit mends it; asking /api/status first keeps 422s out of the console).
async function initialView() {
  for (;;) {
    try {
      const status = await (await fetch('api/status', {cache: 'no-store'})).json();
      page.modelError = status.error ?? '';
      // a recording: a time slider over its length
      page.recording = status.recording;
      $('at-control').hidden = !status.recording;
      if (status.recording) $('at').max = status.recording.duration;
      // a calibrated camera (--camera-info, --camera-frame, --camera-pose) is placed as given
      page.camera = status.camera;
      page.cameraView = status.camera_view;
      for (const id of ['reset-view', 'fit-view', 'focus', 'size']) {
        $(id).disabled = status.camera;
        if (status.camera) $(id).title = 'the view is the calibrated camera urdfsnap serve was given; it is placed as given';
      }
      if (!status.error) {
        const response = await fetch('api/view', {cache: 'no-store'});
        if (response.ok) return response.json();
      }
    } catch (error) {
      page.modelError = 'urdfsnap serve does not answer (' + error.message + '); retrying';
    }
    showError();
    $('status').textContent = 'waiting for the model to load';
    await new Promise((resolve) => setTimeout(resolve, STATUS_POLL_MS));
  }
}

async function start() {
  page.initial = await initialView();
  page.view = viewFromOptions(page.initial.options);
  page.options = optionsFromInitial(page.initial.options);
  wireControls();
  wireOrbit();
  showControls();
  await pollStatus();
  requestFrame();
  setTimeout(pollForever, STATUS_POLL_MS);
}

start();
