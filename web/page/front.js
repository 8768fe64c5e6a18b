// The front panel: for the scenes of the Pareto study (docs/pareto.md: chain, ball_chain,
// mass_ratio), each strategy's front of median largest joint separation against cost in
// sweeps, on log axes, drawn from the study's committed runs (pareto-data.js, generated from
// docs/results/pareto-<scene>.csv when the page is built); the form's settings placed on it;
// and, on request, the same configuration measured in this browser: the study's 9 perturbed
// runs, each one pv_study_run, marked beside the committed point.
'use strict';

const FRONT_TRIALS = 9;  // the study's kTrials (testbed/report/trials.h)

// The median of numbers, NaN sorting last (as the study's).
function medianOf(values) {
  const sorted = [...values].sort((a, b) => {
    if (Number.isNaN(a)) return Number.isNaN(b) ? 0 : 1;
    if (Number.isNaN(b)) return -1;
    return a - b;
  });
  return sorted[Math.floor(sorted.length / 2)];
}

// One configuration of the study: strategy, split, and its runs.
function configKey(solver, substeps, velocity, position) {
  return solver + ' ' + substeps + ' x ' + velocity + '/' + position;
}

// The committed runs of a scene, by configuration.
function parseStudy(csv) {
  const lines = csv.trim().split('\n');
  const column = Object.fromEntries(lines[0].split(',').map((name, i) => [name, i]));
  const configs = new Map();
  for (const line of lines.slice(1)) {
    const f = line.split(',');
    const key = configKey(f[column.solver], f[column.substeps], f[column.velocity_iterations],
                          f[column.position_iterations]);
    if (!configs.has(key)) {
      configs.set(key, { key, solver: f[column.solver], sweeps: Number(f[column.sweeps]),
                         separations: [], torn: 0 });
    }
    const c = configs.get(key);
    c.separations.push(Number(f[column.max_separation_m]));
    c.torn += Number(f[column.torn]);
  }
  for (const c of configs.values()) {
    c.median = medianOf(c.separations);
    c.low = Math.min(...c.separations);
    c.high = Math.max(...c.separations);
  }
  return configs;
}

// A strategy's front: by rising cost, each configuration whose median beats every cheaper one's
// (as pareto_study.cpp's paretoFront).
function frontOf(configs, solver) {
  const mine = [...configs.values()].filter((c) => c.solver === solver);
  mine.sort((a, b) => (a.sweeps - b.sweeps) || (a.median - b.median));
  const front = [];
  for (const c of mine) {
    if (c.median < (front.length ? front[front.length - 1].median : Infinity)) front.push(c);
  }
  return front;
}

function formatRange(median, low, high) {
  const g = (v) => Number(v.toPrecision(3)).toString();
  return g(median) + ' m [' + g(low) + '-' + g(high) + ']';
}

class FrontPanel {
  constructor(api, solverNames, elements) {
    this.api = api;
    this.names = solverNames;
    this.el = elements;  // {panel, canvas, text, measure, result}
    this.ctx = elements.canvas.getContext('2d');
    this.configs = null;
    this.measured = null;
    elements.measure.addEventListener('click', () => this.measureLater());
  }

  // Shows the panel for a scene of the study (hides it for the others).
  setScene(index, name) {
    const csv = typeof PARETO_CSV === 'object' ? PARETO_CSV[name] : undefined;
    this.sceneIndex = index;
    this.sceneName = name;
    this.configs = csv ? parseStudy(csv) : null;
    this.measured = null;
    this.el.panel.hidden = !this.configs;
  }

  // The form's configuration: {solver (index), substeps, velocity, position}.
  update(config) {
    if (!this.configs) return;
    this.config = config;
    const c = this.studied();
    const split = config.substeps + ' x ' + config.velocity + '/' + config.position;
    const sweeps = config.substeps * (config.velocity + config.position);
    let text = this.names[config.solver] + ' ' + split + ' (' + sweeps + ' sweeps): ';
    if (!c) {
      text += 'not in the study\'s grid (substeps 1, 2, 4, 8, 16 x velocity 1, 2, 4, 8 x ' +
              'position 0, 1, 3; Baumgarte at 0)';
    } else {
      const front = frontOf(this.configs, c.solver);
      text += 'the study\'s median ' + formatRange(c.median, c.low, c.high) + ', ' + c.torn +
              '/' + c.separations.length + ' torn, ' +
              (front.includes(c) ? 'on its strategy\'s front' : 'off its strategy\'s front');
    }
    this.el.text.textContent = text;
    if (this.measured && this.measured.key !== this.keyOf(config)) {
      this.measured = null;
      this.el.result.textContent = '';
    }
    this.paint();
  }

  keyOf(config) {
    return configKey(this.names[config.solver], config.substeps, config.velocity,
                     config.position);
  }

  studied() { return this.configs.get(this.keyOf(this.config)); }

  // The form's configuration run as the study runs it, FRONT_TRIALS times here; null if the
  // engine refused a setting (the error is the api's).
  measureNow() {
    const c = this.config;
    const runs = [];
    for (let seed = 1; seed <= FRONT_TRIALS; ++seed) {
      const r = this.api.studyRun(this.sceneIndex, c.solver, c.substeps, c.velocity, c.position,
                                  seed);
      if (Number.isNaN(r)) return null;
      runs.push(r);
    }
    const separations = runs.map(Math.abs);
    this.measured = {
      key: this.keyOf(c), sweeps: c.substeps * (c.velocity + c.position), separations,
      median: medianOf(separations), low: Math.min(...separations),
      high: Math.max(...separations), torn: runs.filter((r) => r < 0).length,
    };
    const m = this.measured, s = this.studied();
    this.el.result.textContent = 'measured here: ' + formatRange(m.median, m.low, m.high) + ', ' +
        m.torn + '/' + FRONT_TRIALS + ' torn' +
        (s ? (s.separations.every((v, i) => Number(v.toPrecision(6)) ===
                                            Number(separations[i].toPrecision(6)))
              ? ': every run as the study\'s' : ': the runs differ from the study\'s')
           : '');
    this.paint();
    return this.measured;
  }

  // The button's measurement, after the page has shown that it runs.
  measureLater() {
    this.el.result.textContent = 'running ' + FRONT_TRIALS + ' runs of 600 steps...';
    setTimeout(() => {
      if (!this.measureNow()) this.el.result.textContent = this.api.error();
    }, 20);
  }

  paint() {
    const ctx = this.ctx, w = this.el.canvas.width, h = this.el.canvas.height;
    // The legend's two rows under the axes, where no point can hide them.
    const left = 34, right = w - 4, top = 4, bottom = h - 38, axisLabels = h - 26;
    const x = (sweeps) => left + (right - left) * Math.log2(Math.max(sweeps, 1)) / 8;  // 1..256
    const y = (v) => {
      const decades = Math.log10(Math.min(Math.max(v, 1e-4), 100)) + 4;  // 0 .. 6
      return bottom - (bottom - top) * decades / 6;
    };
    ctx.clearRect(0, 0, w, h);
    ctx.font = '10px sans-serif';
    ctx.fillStyle = '#98a2ad';
    ctx.strokeStyle = '#3a4048';
    for (const [v, label] of [[1e-4, '0.1 mm'], [1e-2, '1 cm'], [1, '1 m'], [100, '100 m']]) {
      ctx.beginPath(); ctx.moveTo(left, y(v)); ctx.lineTo(right, y(v)); ctx.stroke();
      ctx.fillText(label, 0, y(v) + 3);
    }
    ctx.textAlign = 'center';
    for (const s of [1, 4, 16, 64]) ctx.fillText(String(s), x(s), axisLabels);
    ctx.textAlign = 'right';
    ctx.fillText('256 sweeps', right, axisLabels);
    ctx.textAlign = 'left';
    this.names.forEach((name, s) => {
      const front = frontOf(this.configs, name);
      if (!front.length) return;
      ctx.strokeStyle = ctx.fillStyle = PLOT_COLORS[s % PLOT_COLORS.length];
      ctx.beginPath();
      front.forEach((c, k) => {
        if (k) ctx.lineTo(x(c.sweeps), y(c.median)); else ctx.moveTo(x(c.sweeps), y(c.median));
      });
      ctx.stroke();
      for (const c of front) ctx.fillRect(x(c.sweeps) - 1.5, y(c.median) - 1.5, 3, 3);
      ctx.fillText(name, left + 4 + 90 * (s % 3), h - 13 + 11 * Math.floor(s / 3));
    });
    const studied = this.config && this.studied();
    if (studied) {  // the form's configuration, as the study measured it: a ring
      ctx.strokeStyle = '#ffffff';
      ctx.beginPath();
      ctx.arc(x(studied.sweeps), y(studied.median), 5, 0, 2 * Math.PI);
      ctx.stroke();
    }
    if (this.measured) {  // and as measured here: a cross
      const px = x(this.measured.sweeps), py = y(this.measured.median);
      ctx.strokeStyle = '#ffffff';
      ctx.beginPath();
      ctx.moveTo(px - 4, py - 4); ctx.lineTo(px + 4, py + 4);
      ctx.moveTo(px - 4, py + 4); ctx.lineTo(px + 4, py - 4);
      ctx.stroke();
    }
  }
}
