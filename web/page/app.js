// The browser testbed: runs a testbed scene in pivot2d (pivot-web.js, the engine compiled to
// WebAssembly) in real time at 60 steps a second, draws it, and lets the user drag bodies,
// inspect and re-solve joints, and change the world's settings. window.pivotApp is what
// selftest.js drives.
'use strict';

const STEP_SECONDS = 1 / 60;
const HANDS = { stiff: { hertz: 30, forcePerKg: 50000 }, soft: { hertz: 5, forcePerKg: 1000 } };

const $ = (id) => document.getElementById(id);

class App {
  constructor(module) {
    this.m = module;
    const c = (name, ret, args) => module.cwrap(name, ret, args);
    const n = 'number', s = 'string';
    this.api = {
      sceneCount: c('pv_scene_count', n, []), sceneName: c('pv_scene_name', s, [n]),
      sceneDescription: c('pv_scene_description', s, [n]),
      solverCount: c('pv_solver_count', n, []), solverName: c('pv_solver_name', s, [n]),
      load: c('pv_load', n, [n, n, n, n, n, n, n, n]), reload: c('pv_reload', n, []),
      setSettings: c('pv_set_settings', n, [n, n, n, n, n, n, n]),
      step: c('pv_step', n, []), error: c('pv_error', s, []),
      draw: c('pv_draw', n, []), drawList: c('pv_draw_list', n, []),
      grab: c('pv_grab', n, [n, n, n, n]), moveHand: c('pv_move_hand', null, [n, n]),
      release: c('pv_release', null, []),
      jointCount: c('pv_joint_count', n, []), jointNear: c('pv_joint_near', n, [n, n, n]),
      jointValid: c('pv_joint_valid', n, [n]), jointType: c('pv_joint_type', s, [n]),
      jointSeparation: c('pv_joint_separation', n, [n]),
      jointAnchor: c('pv_joint_anchor', n, [n, n, n]),
      jointSolver: c('pv_joint_solver', n, [n]),
      setJointSolver: c('pv_set_joint_solver', n, [n, n]),
      jointBias: c('pv_joint_bias', n, [n]), setJointBias: c('pv_set_joint_bias', n, [n, n]),
      jointHertz: c('pv_joint_hertz', n, [n]), setJointHertz: c('pv_set_joint_hertz', n, [n, n]),
      largestSeparation: c('pv_largest_separation', n, [n]), stat: c('pv_stat', n, [n]),
      studyRun: c('pv_study_run', n, [n, n, n, n, n, n]),
    };
    this.solverNames = [];
    for (let s = 0; s < this.api.solverCount(); ++s) this.solverNames.push(this.api.solverName(s));
    this.view = new WorldView($('world'));
    this.plot = new SeparationPlot($('plot'), this.solverNames);
    this.front = new FrontPanel(this.api, this.solverNames, {
      panel: $('front-panel'), canvas: $('front'), text: $('front-config'),
      measure: $('front-measure'), result: $('front-measured') });
    this.paused = false;
    this.selectedJoint = -1;
    this.pointer = null;  // the hand's target while the user drags, world coordinates
    this.panning = null;
    this.lastTime = null;
    this.owed = 0;  // seconds of simulation the clock is ahead of the world
    this.frameMs = 0;
    this.stepMsAverage = 0;
    this.fillControls();
    this.bindControls();
    this.bindPointer();
  }

  fillControls() {
    for (let i = 0; i < this.api.sceneCount(); ++i) {
      $('scene').add(new Option(this.api.sceneName(i), i));
    }
    this.solverNames.forEach((name, s) => {
      $('solver').add(new Option(name, s));
      $('joint-solver').add(new Option(name, s));
    });
    $('solver').value = String(this.solverNames.indexOf('full_ngs'));
  }

  bindControls() {
    $('scene').addEventListener('change', () => this.load());
    $('reset').addEventListener('click', () => this.load());
    // The solver and bias are every joint's at load (then each joint's own, in its panel); the
    // rest applies from the next step.
    for (const id of ['contacts', 'substeps', 'velocity-iterations', 'position-iterations',
                      'script']) {
      $(id).addEventListener('change', () => {
        if (!this.check(this.api.setSettings(...this.settings()))) this.showSettings();
        this.showFront();
      });
    }
    $('solver').addEventListener('change', () => this.showFront());
    $('pause').addEventListener('click', () => this.setPaused(!this.paused));
    $('single-step').addEventListener('click', () => { this.setPaused(true); this.stepOnce(); });
    $('joint-solver').addEventListener('change', () => {
      this.check(this.api.setJointSolver(this.selectedJoint, Number($('joint-solver').value)));
      this.showJoint();
    });
    $('joint-bias').addEventListener('change', () => {
      this.check(this.api.setJointBias(this.selectedJoint, Number($('joint-bias').value)));
      this.showJoint();
    });
    $('joint-bias-default').addEventListener('click', () => {
      this.check(this.api.setJointBias(this.selectedJoint, -1));
      this.showJoint();
    });
    $('joint-hertz').addEventListener('change', () => {
      this.check(this.api.setJointHertz(this.selectedJoint, Number($('joint-hertz').value)));
      this.showJoint();
    });
  }

  bindPointer() {
    const canvas = $('world');
    // The pointer in canvas pixels (the page may show the canvas scaled).
    const pixel = (e) => {
      const r = canvas.getBoundingClientRect();
      return { x: (e.clientX - r.left) * canvas.width / r.width,
               y: (e.clientY - r.top) * canvas.height / r.height };
    };
    const at = (e) => { const p = pixel(e); return this.view.toWorld(p.x, p.y); };
    canvas.addEventListener('contextmenu', (e) => e.preventDefault());
    canvas.addEventListener('pointerdown', (e) => {
      if (e.button === 2) { this.panning = { x: e.clientX, y: e.clientY }; return; }
      const p = at(e);
      // A joint's anchor under the pointer is selected; otherwise the body there is grabbed.
      const joint = this.api.jointNear(p.x, p.y, 8 / this.view.scale);
      if (joint >= 0) { this.selectJoint(joint); return; }
      const hand = HANDS[$('hand').value];
      // No body there is not an error: the press simply grabs nothing.
      if (this.api.grab(p.x, p.y, hand.hertz, hand.forcePerKg)) {
        this.pointer = p;
        canvas.setPointerCapture?.(e.pointerId);
      }
    });
    canvas.addEventListener('pointermove', (e) => {
      if (this.panning) {
        this.view.pan(e.clientX - this.panning.x, e.clientY - this.panning.y);
        this.panning = { x: e.clientX, y: e.clientY };
      } else if (this.pointer) {
        this.pointer = at(e);
        this.api.moveHand(this.pointer.x, this.pointer.y);
      }
    });
    const up = () => {
      if (this.pointer) this.api.release();
      this.pointer = null;
      this.panning = null;
    };
    canvas.addEventListener('pointerup', up);
    canvas.addEventListener('pointercancel', up);
    canvas.addEventListener('wheel', (e) => {
      e.preventDefault();
      const p = pixel(e);
      this.view.zoom(e.deltaY < 0 ? 1.15 : 1 / 1.15, p.x, p.y);
    }, { passive: false });
  }

  // The world settings of the form, as pv_load and pv_set_settings take them (an empty bias:
  // each solver's default).
  settings() {
    const bias = $('bias').value.trim();
    return [Number($('solver').value), bias === '' ? -1 : Number(bias),
      Number($('contacts').value), Number($('substeps').value),
      Number($('velocity-iterations').value), Number($('position-iterations').value),
      $('script').checked ? 1 : 0];
  }

  // The form's world settings as the world has them (after a refused change).
  showSettings() {
    $('substeps').value = this.api.stat(8);
    $('contacts').value = this.api.stat(9);
    $('velocity-iterations').value = this.api.stat(10);
    $('position-iterations').value = this.api.stat(11);
  }

  // Builds the chosen scene with the world settings of the form.
  load() {
    const ok = this.api.load(Number($('scene').value), ...this.settings());
    if (!this.check(ok)) return false;
    const scene = Number($('scene').value);
    $('scene-description').textContent = this.api.sceneDescription(scene);
    this.front.setScene(scene, this.api.sceneName(scene));
    this.showFront();
    this.pointer = null;
    this.selectJoint(-1);
    this.plot.clear();
    const count = this.api.draw();
    this.view.fit(this.drawList(count), count);
    this.owed = 0;
    return true;
  }

  // The form's solver, substeps and iterations on the study's front (for its scenes).
  showFront() {
    this.front.update({ solver: Number($('solver').value), substeps: Number($('substeps').value),
                        velocity: Number($('velocity-iterations').value),
                        position: Number($('position-iterations').value) });
  }

  drawList(count) {
    return new Float32Array(this.m.HEAPF32.buffer, this.api.drawList(), count);
  }

  check(ok) {
    $('error').textContent = ok ? '' : this.api.error();
    return Boolean(ok);
  }

  setPaused(paused) {
    this.paused = paused;
    $('pause').textContent = paused ? 'run' : 'pause';
  }

  stepOnce() {
    if (!this.check(this.api.step())) { this.setPaused(true); return; }
    const ms = this.api.stat(0);
    this.stepMsAverage += 0.05 * (ms - this.stepMsAverage);
    this.plot.push(this.solverNames.map((_, s) => this.api.largestSeparation(s)));
  }

  selectJoint(index) {
    this.selectedJoint = index;
    $('joint-panel').hidden = index < 0;
    if (index >= 0) this.showJoint();
  }

  showJoint() {
    const j = this.selectedJoint;
    if (j < 0 || !this.api.jointValid(j)) { this.selectJoint(-1); return; }
    $('joint-name').textContent = '#' + j + ' (' + this.api.jointType(j) + ')';
    $('joint-solver').value = String(this.api.jointSolver(j));
    // A field being typed into keeps what the user typed.
    if (document.activeElement !== $('joint-bias')) {
      $('joint-bias').value = this.api.jointBias(j).toFixed(2);
    }
    if (document.activeElement !== $('joint-hertz')) {
      $('joint-hertz').value = this.api.jointHertz(j);
    }
  }

  // What a frame does for one step, without the clock (the self-test's steps): move the hand
  // to the pointer, step, and draw.
  frameStep() {
    if (this.pointer) this.api.moveHand(this.pointer.x, this.pointer.y);
    this.stepOnce();
    this.render();
  }

  // One animation frame: the steps the clock owes (at most 4, so a slow frame does not snowball),
  // then the picture and the panels.
  frame(time) {
    const start = performance.now();
    if (this.lastTime !== null && !this.paused) {
      this.owed += Math.min((time - this.lastTime) / 1000, 0.1) * Number($('speed').value);
      let steps = 0;
      while (this.owed >= STEP_SECONDS && steps < 4) {
        if (this.pointer) this.api.moveHand(this.pointer.x, this.pointer.y);
        this.stepOnce();
        this.owed -= STEP_SECONDS;
        ++steps;
      }
      if (steps === 4) this.owed = 0;
    }
    this.lastTime = time;
    this.render();
    this.frameMs += 0.05 * (performance.now() - start - this.frameMs);
  }

  render() {
    const count = this.api.draw();
    let selected = null;
    if (this.selectedJoint >= 0 && this.api.jointValid(this.selectedJoint)) {
      selected = { x: this.api.jointAnchor(this.selectedJoint, 1, 0),
                   y: this.api.jointAnchor(this.selectedJoint, 1, 1) };
      $('joint-separation').textContent =
        formatMetres(this.api.jointSeparation(this.selectedJoint));
    }
    this.view.paint(this.drawList(count), count, selected);
    this.plot.paint();
    const st = (k) => this.api.stat(k);
    $('stats').textContent =
      'step ' + this.stepMsAverage.toFixed(3) + ' ms, frame ' + this.frameMs.toFixed(2) +
      ' ms (budget 16.7)\n' +
      'steps ' + st(7) + ', bodies simulated ' + st(1) + ', islands ' + st(2) + '\n' +
      'contacts ' + st(3) + ' (touching ' + st(4) + '), joints ' + st(5) +
      ', asleep ' + st(6);
  }

  run() {
    const loop = (time) => { this.frame(time); requestAnimationFrame(loop); };
    requestAnimationFrame(loop);
  }
}

function formatMetres(m) {
  if (!(m >= 0)) return String(m);
  if (m < 1e-3) return (m * 1e6).toFixed(1) + ' um';
  if (m < 1) return (m * 1e3).toFixed(2) + ' mm';
  return m.toFixed(3) + ' m';
}

window.pivotReady = createPivot().then((module) => {
  const app = new App(module);
  const params = new URLSearchParams(location.search);
  const scene = params.get('scene');
  if (scene) {
    const index = [...$('scene').options].findIndex((o) => o.text === scene);
    if (index >= 0) $('scene').value = String(index);
  }
  app.load();
  if (!params.has('selftest')) app.run();
  window.pivotApp = app;
  return app;
});
