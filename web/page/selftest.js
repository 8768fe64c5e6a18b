// The page's self-test (index.html?selftest), run by ctest in headless Chromium
// (tests/browser/run_web_selftest.cmake): drives the page as a user would, through pointer
// events on the canvas and the joint panel's controls, and writes what it measured into
// #test-result, which the driver reads from the dumped page. Checks:
//  - the seed note's "drag the simple pendulum in a circle quickly and the joint will separate":
//    the pendulum_drag scene's ball, its script off, dragged by the page's hand round the
//    testbed's path (a 3 m circle about the pivot, the rate rising to 4 rev/s over 3 s):
//    the PseudoVelocity joint opens by more than 10 cm, the FullNGS one by less than 1 mm;
//  - a joint's solver changed from its panel takes effect at the next step: the spinning
//    pendulum held by FullNGS, switched to pseudo_velocity, opens at once;
//  - the world's settings change from the form at once, and a value the engine refuses shows
//    its message and changes nothing; the world's bias reaches every joint at reset, and a bias
//    the engine refuses leaves the running scene as it was;
//  - the front panel: shown for chain (a scene of the Pareto study) with the form's FullNGS
//    1 x 2/1 placed on the study's front, hidden for the pendulum; and that configuration's 9
//    perturbed runs measured in the browser tear as often as the study's and have their median
//    within the study's range. Not each run to the bit: the engine turns angles into rotations
//    with the C library's sine and cosine, whose last bits differ between glibc (the native
//    build) and Emscripten's musl, so some runs differ from the sixth digit on (how many agree
//    is printed);
//  - the page steps and draws, and nothing was logged as an error.
'use strict';

(function () {
  if (!new URLSearchParams(location.search).has('selftest')) return;
  const errors = [];
  const originalError = console.error;
  console.error = (...args) => { errors.push(args.join(' ')); originalError.apply(console, args); };
  window.addEventListener('error', (e) => errors.push('uncaught: ' + e.message));
  window.addEventListener('unhandledrejection', (e) => errors.push('rejected: ' + e.reason));

  const report = (lines, pass) => {
    const out = document.getElementById('test-result');
    out.hidden = false;
    out.textContent = 'selftest: ' + (pass ? 'pass' : 'FAIL') + '\n' + lines.join('\n');
  };

  function pointer(app, type, x, y) {
    const canvas = document.getElementById('world');
    const r = canvas.getBoundingClientRect();
    const p = app.view.toScreen(x, y);
    canvas.dispatchEvent(new PointerEvent(type, {
      bubbles: true, button: 0, pointerId: 1, isPrimary: true,
      clientX: r.left + p.x * r.width / canvas.width,
      clientY: r.top + p.y * r.height / canvas.height,
    }));
  }

  function choose(id, value) {
    const element = document.getElementById(id);
    element.value = String(value);
    element.dispatchEvent(new Event('change'));
  }

  function loadScene(app, name, solver, script) {
    choose('solver', app.solverNames.indexOf(solver));
    document.getElementById('script').checked = script;
    const index = [...document.getElementById('scene').options].findIndex((o) => o.text === name);
    choose('scene', index);  // loads it
  }

  // The testbed's drag (scenes/drag.cpp): grab the ball at rest 5 m below the pivot,
  // then pull it round a 3 m circle whose rate rises to 4 rev/s at 3 s; returns the largest
  // separation of the solver's joints.
  function whirl(app, solver) {
    loadScene(app, 'pendulum_drag', solver, false);
    const pivot = { x: 0, y: 10 };
    pointer(app, 'pointerdown', pivot.x, pivot.y - 5);
    if (!app.pointer) throw new Error('the hand did not take the ball');
    const s = app.solverNames.indexOf(solver);
    let largest = 0;
    const duration = 3, finalRate = 4 * 2 * Math.PI;
    for (let step = 0; step < 180; ++step) {
      const t = (step + 1) / 60;
      const angle = 0.5 * finalRate * t * t / duration;
      pointer(app, 'pointermove', pivot.x + 3 * Math.sin(angle), pivot.y - 3 * Math.cos(angle));
      app.frameStep();
      largest = Math.max(largest, app.api.largestSeparation(s));
    }
    pointer(app, 'pointerup', pivot.x, pivot.y);
    return largest;
  }

  function switchSolver(app) {
    loadScene(app, 'pendulum', 'full_ngs', true);
    app.frameStep();
    const before = app.api.jointSeparation(0);
    // Click the pivot's anchor: the panel opens on joint 0; choose pseudo_velocity there.
    pointer(app, 'pointerdown', app.api.jointAnchor(0, 0, 0), app.api.jointAnchor(0, 0, 1));
    pointer(app, 'pointerup', 0, 0);
    if (app.selectedJoint !== 0) throw new Error('clicking the anchor did not select the joint');
    const pseudo = app.solverNames.indexOf('pseudo_velocity');
    choose('joint-solver', pseudo);
    const reported = app.api.jointSolver(0);
    app.frameStep();
    const after = app.api.jointSeparation(0);
    return { before, after, reported, pseudo };
  }

  // The chain at FullNGS 1 x 2/1 on the front panel, measured here, then the pendulum.
  function front(app) {
    choose('substeps', 1);
    choose('contacts', 1);  // NGS, the study's
    choose('velocity-iterations', 2);
    choose('position-iterations', 1);
    loadScene(app, 'chain', 'full_ngs', true);
    const shown = !document.getElementById('front-panel').hidden;
    const studied = app.front.studied();
    const measured = app.front.measureNow();
    const text = document.getElementById('front-config').textContent;
    loadScene(app, 'pendulum', 'full_ngs', true);
    return { shown, studied, measured, text,
             hidden: document.getElementById('front-panel').hidden };
  }

  window.pivotReady.then((app) => {
    const lines = [];
    let pass = true;
    const expect = (ok, line) => {
      lines.push((ok ? 'ok   ' : 'FAIL ') + line);
      pass = pass && ok;
    };
    try {
      const pseudo = whirl(app, 'pseudo_velocity');
      expect(pseudo > 0.10, 'whirled pendulum, pseudo_velocity: largest separation ' +
             pseudo.toFixed(4) + ' m (> 0.1)');
      const full = whirl(app, 'full_ngs');
      expect(full < 0.001, 'whirled pendulum, full_ngs: largest separation ' +
             full.toExponential(2) + ' m (< 0.001)');
      const sw = switchSolver(app);
      expect(sw.reported === sw.pseudo,
             'joint panel set the solver to ' + app.solverNames[sw.reported]);
      expect(sw.before < 0.001 && sw.after > 0.01, 'spinning pendulum: separation ' +
             sw.before.toExponential(2) + ' m with full_ngs, ' + sw.after.toExponential(2) +
             ' m one step after the switch (< 0.001, then > 0.01)');
      expect(app.api.stat(7) === 2, 'steps counted: ' + app.api.stat(7));
      choose('substeps', 4);
      choose('contacts', 2);  // soft
      const set = app.api.stat(8) === 4 && app.api.stat(9) === 2;
      expect(set, 'substeps and contacts set from the form: ' + app.api.stat(8) + ', ' +
             app.api.stat(9));
      choose('substeps', 0);
      const message = document.getElementById('error').textContent;
      const shown = document.getElementById('substeps').value;
      expect(app.api.stat(8) === 4 && message.length > 0 && shown === '4',
             'substeps 0 refused ("' + message + '"), still ' + app.api.stat(8) +
             ', the form shows ' + shown);
      document.getElementById('bias').value = '0.1';
      loadScene(app, 'bridge', 'baumgarte', true);
      const joints = app.api.jointCount();
      const biased = Math.abs(app.api.jointBias(0) - 0.1) < 1e-6 &&
                     Math.abs(app.api.jointBias(joints - 1) - 0.1) < 1e-6;
      expect(biased, 'bias 0.1 on every one of the bridge\'s ' + joints + ' joints');
      document.getElementById('bias').value = '1.5';
      document.getElementById('reset').click();
      const refusal = document.getElementById('error').textContent;
      expect(refusal.length > 0 && Math.abs(app.api.jointBias(0) - 0.1) < 1e-6,
             'bias 1.5 refused ("' + refusal + '"), the bridge kept 0.1');
      document.getElementById('bias').value = '';
      const f = front(app);
      expect(f.shown && f.hidden, 'front panel shown for chain, hidden for pendulum');
      expect(Boolean(f.studied) && f.text.includes('on its strategy\'s front'),
             'chain, full_ngs 1 x 2/1 on the study\'s front: "' + f.text + '"');
      const s = f.studied, m = f.measured;
      const agree = s && m ? s.separations.filter((v, i) =>
        v === Number(m.separations[i].toPrecision(6))).length : 0;
      expect(Boolean(s && m) && m.torn === s.torn && m.median >= s.low && m.median <= s.high,
             'measured here: median ' + (m ? m.median.toPrecision(6) : '-') + ' m, ' +
             (m ? m.torn : '-') + ' torn, against the study\'s [' + (s ? s.low : '-') + ', ' +
             (s ? s.high : '-') + '], ' + (s ? s.torn : '-') + ' torn; ' + agree +
             ' of 9 runs to the bit');
      const count = app.api.draw();
      expect(count > 0, 'draw list: ' + count + ' numbers');
    } catch (e) {
      expect(false, 'exception: ' + e.message);
    }
    expect(errors.length === 0, 'console errors: ' + (errors.length ? errors.join(' | ') : 'none'));
    report(lines, pass);
  }, (e) => report(['the page did not start: ' + e], false));
})();
