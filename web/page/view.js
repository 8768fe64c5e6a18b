// The world view: metres to canvas pixels (y up), fitted to a scene when it loads, panned and
// zoomed by the user; and the painting of the engine's draw list (web_session.h, DrawCode).
'use strict';

class WorldView {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext('2d');
    this.scale = 20;  // pixels per metre
    this.center = { x: 0, y: 0 };
  }

  toScreen(x, y) {
    return { x: this.canvas.width / 2 + (x - this.center.x) * this.scale,
             y: this.canvas.height / 2 - (y - this.center.y) * this.scale };
  }

  toWorld(px, py) {
    return { x: this.center.x + (px - this.canvas.width / 2) / this.scale,
             y: this.center.y - (py - this.canvas.height / 2) / this.scale };
  }

  // Frames what moves (everything not drawn in the static colour, debug_draw.h's kStatic), or
  // everything if nothing moves, with a margin: a long ground would shrink the rest to nothing.
  fit(list, count) {
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (const moving of [true, false]) {
      forEachPoint(list, count, (x, y, isStatic) => {
        if (moving && isStatic) return;
        minX = Math.min(minX, x); maxX = Math.max(maxX, x);
        minY = Math.min(minY, y); maxY = Math.max(maxY, y);
      });
      if (maxX >= minX) break;
    }
    if (!(maxX >= minX)) return;
    // Very long grounds would shrink everything else to nothing: at most 120 m across.
    const width = Math.min(Math.max(maxX - minX, 4), 120);
    const height = Math.min(Math.max(maxY - minY, 4), 120);
    this.center = { x: (minX + maxX) / 2, y: (minY + maxY) / 2 };
    this.scale = 0.85 * Math.min(this.canvas.width / width, this.canvas.height / height);
  }

  zoom(factor, px, py) {
    const before = this.toWorld(px, py);
    this.scale = Math.min(Math.max(this.scale * factor, 0.5), 2000);
    const after = this.toWorld(px, py);
    this.center.x += before.x - after.x;
    this.center.y += before.y - after.y;
  }

  pan(dx, dy) {
    this.center.x -= dx / this.scale;
    this.center.y += dy / this.scale;
  }

  paint(list, count, selected) {
    const ctx = this.ctx;
    ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
    ctx.lineWidth = 1;
    let i = 0;
    while (i < count) {
      const code = list[i];
      const color = rgb(list[i + 1], list[i + 2], list[i + 3]);
      i += 4;
      switch (code) {
        case 1: {  // polygon: radius, n, points
          const radius = list[i], n = list[i + 1];
          ctx.beginPath();
          for (let k = 0; k < n; ++k) {
            const p = this.toScreen(list[i + 2 + 2 * k], list[i + 3 + 2 * k]);
            if (k === 0) ctx.moveTo(p.x, p.y); else ctx.lineTo(p.x, p.y);
          }
          ctx.closePath();
          this.fillAndStroke(color, radius);
          i += 2 + 2 * n;
          break;
        }
        case 2: {  // circle: x, y, radius, axis
          const c = this.toScreen(list[i], list[i + 1]);
          const r = list[i + 2] * this.scale;
          ctx.beginPath();
          ctx.arc(c.x, c.y, r, 0, 2 * Math.PI);
          this.fillAndStroke(color, 0);
          ctx.beginPath();
          ctx.moveTo(c.x, c.y);
          ctx.lineTo(c.x + r * list[i + 3], c.y - r * list[i + 4]);
          ctx.stroke();
          i += 5;
          break;
        }
        case 3: {  // capsule: p1, p2, radius
          const a = this.toScreen(list[i], list[i + 1]);
          const b = this.toScreen(list[i + 2], list[i + 3]);
          ctx.save();
          ctx.lineCap = 'round';
          ctx.lineWidth = 2 * list[i + 4] * this.scale;
          ctx.strokeStyle = color;
          ctx.globalAlpha = 0.55;
          ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y); ctx.stroke();
          ctx.restore();
          i += 5;
          break;
        }
        case 4: {  // segment
          const a = this.toScreen(list[i], list[i + 1]);
          const b = this.toScreen(list[i + 2], list[i + 3]);
          ctx.strokeStyle = color;
          ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y); ctx.stroke();
          i += 4;
          break;
        }
        case 5: {  // point: x, y, size in pixels
          const p = this.toScreen(list[i], list[i + 1]);
          const s = list[i + 2];
          ctx.fillStyle = color;
          ctx.fillRect(p.x - s / 2, p.y - s / 2, s, s);
          i += 3;
          break;
        }
        case 6: {  // joint: anchor A, anchor B, separation
          const a = this.toScreen(list[i], list[i + 1]);
          const b = this.toScreen(list[i + 2], list[i + 3]);
          ctx.strokeStyle = color;
          ctx.lineWidth = 2;
          ctx.beginPath(); ctx.moveTo(a.x, a.y); ctx.lineTo(b.x, b.y); ctx.stroke();
          ctx.lineWidth = 1;
          ctx.fillStyle = color;
          ctx.beginPath(); ctx.arc(a.x, a.y, 3, 0, 2 * Math.PI); ctx.fill();
          ctx.beginPath(); ctx.arc(b.x, b.y, 3, 0, 2 * Math.PI); ctx.fill();
          i += 5;
          break;
        }
        default:
          throw new Error('unknown draw code ' + code);
      }
    }
    if (selected) {
      const p = this.toScreen(selected.x, selected.y);
      ctx.strokeStyle = '#ffffff';
      ctx.lineWidth = 2;
      ctx.beginPath(); ctx.arc(p.x, p.y, 9, 0, 2 * Math.PI); ctx.stroke();
      ctx.lineWidth = 1;
    }
  }

  fillAndStroke(color, radius) {
    const ctx = this.ctx;
    ctx.fillStyle = color;
    ctx.globalAlpha = 0.5;
    ctx.fill();
    ctx.globalAlpha = 1;
    ctx.strokeStyle = color;
    if (radius > 0) {
      ctx.lineWidth = Math.max(1, 2 * radius * this.scale);
      ctx.lineJoin = 'round';
    }
    ctx.stroke();
    ctx.lineWidth = 1;
  }
}

function rgb(r, g, b) {
  return 'rgb(' + Math.round(255 * r) + ',' + Math.round(255 * g) + ',' + Math.round(255 * b) + ')';
}

// Calls f(x, y, isStatic) for every world point in a draw list.
function forEachPoint(list, count, visit) {
  let i = 0;
  while (i < count) {
    const code = list[i];
    // debug_colors::kStatic, as floats
    const isStatic = Math.abs(list[i + 1] - 0.55) < 1e-3 && Math.abs(list[i + 2] - 0.58) < 1e-3;
    const f = (x, y) => visit(x, y, isStatic);
    i += 4;
    if (code === 1) {
      const n = list[i + 1];
      for (let k = 0; k < n; ++k) f(list[i + 2 + 2 * k], list[i + 3 + 2 * k]);
      i += 2 + 2 * n;
    } else if (code === 2) { f(list[i], list[i + 1]); i += 5; }
    else if (code === 3) { f(list[i], list[i + 1]); f(list[i + 2], list[i + 3]); i += 5; }
    else if (code === 4) { f(list[i], list[i + 1]); f(list[i + 2], list[i + 3]); i += 4; }
    else if (code === 5) { f(list[i], list[i + 1]); i += 3; }
    else if (code === 6) { f(list[i], list[i + 1]); f(list[i + 2], list[i + 3]); i += 5; }
    else return;
  }
}
