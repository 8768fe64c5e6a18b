// The live plot: for each position solver some joint uses, the largest separation among its
// joints, step by step over the last 600 steps (10 s), on a log scale from 10 micrometres to 10 m.
'use strict';

const PLOT_STEPS = 600;
const PLOT_COLORS = ['#e6a04a', '#e05d5d', '#b07fe0', '#5fb0e6', '#6cc58a', '#d8d36a'];

class SeparationPlot {
  constructor(canvas, solverNames) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.names = solverNames;
    this.clear();
  }

  clear() { this.series = this.names.map(() => []); }

  // separations[s]: the largest separation of solver s's joints this step, or < 0 for none.
  push(separations) {
    separations.forEach((value, s) => {
      const line = this.series[s];
      line.push(value);
      if (line.length > PLOT_STEPS) line.shift();
    });
  }

  paint() {
    const ctx = this.ctx, w = this.canvas.width, h = this.canvas.height;
    const left = 34, bottom = h - 4, top = 4;
    const y = (v) => {
      const decades = Math.log10(Math.min(Math.max(v, 1e-5), 10)) + 5;  // 0 .. 6
      return bottom - (bottom - top) * decades / 6;
    };
    ctx.clearRect(0, 0, w, h);
    ctx.font = '10px sans-serif';
    ctx.fillStyle = '#98a2ad';
    ctx.strokeStyle = '#3a4048';
    const grid = [[1e-5, '10 \u00b5m'], [1e-3, '1 mm'], [1e-1, '10 cm'], [10, '10 m']];
    for (const [v, label] of grid) {
      ctx.beginPath(); ctx.moveTo(left, y(v)); ctx.lineTo(w, y(v)); ctx.stroke();
      ctx.fillText(label, 0, y(v) + 3);
    }
    let legend = 0;
    this.series.forEach((line, s) => {
      if (!line.some((v) => v >= 0)) return;
      ctx.strokeStyle = PLOT_COLORS[s % PLOT_COLORS.length];
      ctx.beginPath();
      let drawing = false;
      line.forEach((v, k) => {
        const x = left + (w - left) * k / (PLOT_STEPS - 1);
        if (v < 0) { drawing = false; return; }
        if (drawing) ctx.lineTo(x, y(v)); else ctx.moveTo(x, y(v));
        drawing = true;
      });
      ctx.stroke();
      ctx.fillStyle = ctx.strokeStyle;
      const column = legend % 3, row = Math.floor(legend / 3);
      ctx.fillText(this.names[s], left + 4 + 80 * column, top + 10 + 11 * row);
      ++legend;
    });
  }
}
