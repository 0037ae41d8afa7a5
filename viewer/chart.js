// The progress chart of the replay viewer: c(t) and m(t) (docs/model.md §4) with T_c and T_m marked
// and the current time as a vertical line. Axes and curves are drawn once per layout into a
// background canvas; a frame only copies it and adds the time line.
'use strict';

(function (hv) {
  const {COLORS, rgb} = hv.palette;

  // 1, 2, 5 × 10^k at least `raw`.
  function niceStep(raw) {
    if (!(raw > 0)) return 1;
    const p = Math.pow(10, Math.floor(Math.log10(raw)));
    for (const m of [1, 2, 5, 10]) if (m * p >= raw) return Math.max(1, m * p);
    return 10 * p;
  }

  class ProgressChart {
    constructor(replay, canvas) {
      this.replay = replay;
      this.canvas = canvas;
      this.dpr = 1;
    }

    layout(dpr) {
      this.dpr = dpr;
      const w = this.canvas.clientWidth || 600;
      const h = this.canvas.clientHeight || 220;
      this.canvas.width = Math.round(w * dpr);
      this.canvas.height = Math.round(h * dpr);
      this.size = {w, h, left: 44, right: 12, top: 12, bottom: 26};
      this.background = this.drawBackground();
    }

    x(t) {
      const s = this.size;
      return s.left + ((s.w - s.left - s.right) * t) / Math.max(1, this.replay.lastT);
    }

    y(percent) {
      const s = this.size;
      return s.top + ((s.h - s.top - s.bottom) * (100 - percent)) / 100;
    }

    timeAt(px) {
      const s = this.size;
      return Math.round(((px - s.left) / (s.w - s.left - s.right)) * this.replay.lastT);
    }

    // Axes, both series and the T_c / T_m markers, drawn once per layout.
    drawBackground() {
      const r = this.replay;
      const s = this.size;
      const canvas = document.createElement('canvas');
      canvas.width = this.canvas.width;
      canvas.height = this.canvas.height;
      const ctx = canvas.getContext('2d');
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      ctx.font = '11px system-ui, sans-serif';
      ctx.fillStyle = '#5c6570';
      ctx.strokeStyle = '#e3e6ea';
      ctx.lineWidth = 1;
      ctx.textAlign = 'right';
      ctx.textBaseline = 'middle';
      for (let p = 0; p <= 100; p += 25) {
        const y = Math.round(this.y(p)) + 0.5;
        ctx.beginPath();
        ctx.moveTo(s.left, y);
        ctx.lineTo(s.w - s.right, y);
        ctx.stroke();
        ctx.fillText(`${p} %`, s.left - 4, y);
      }
      const tick = niceStep(r.lastT / 8);
      ctx.textAlign = 'center';
      ctx.textBaseline = 'top';
      for (let t = 0; t <= r.lastT; t += tick) {
        const x = Math.round(this.x(t)) + 0.5;
        ctx.beginPath();
        ctx.moveTo(x, s.top);
        ctx.lineTo(x, s.h - s.bottom);
        ctx.stroke();
        const label = `${t}`;
        const half = ctx.measureText(label).width / 2;
        ctx.fillText(label, Math.min(x, s.w - half - 1), s.h - s.bottom + 4);
      }
      ctx.textAlign = 'right';
      ctx.fillText('t (s)', s.left - 8, s.h - s.bottom + 4);
      const series = [['m', 'rgb(31, 111, 235)'], ['c', rgb(COLORS.inspected)]];
      for (const [key, color] of series) {
        ctx.strokeStyle = color;
        ctx.lineWidth = 2;
        ctx.beginPath();
        for (let t = 0; t <= r.lastT; ++t) {
          const v = r.coverage(t)[key];
          if (t === 0) ctx.moveTo(this.x(t), this.y(v)); else ctx.lineTo(this.x(t), this.y(v));
        }
        ctx.stroke();
      }
      const marks = [['T_c', r.trace.result.T_c, rgb(COLORS.inspected)], ['T_m', r.trace.result.T_m, 'rgb(31, 111, 235)']];
      ctx.setLineDash([4, 3]);
      ctx.textAlign = 'left';
      ctx.textBaseline = 'top';
      ctx.font = '600 11px system-ui, sans-serif';
      marks.forEach(([name, t, color], i) => {
        if (t === null || t === undefined) return;
        const x = this.x(t);
        ctx.strokeStyle = color;
        ctx.lineWidth = 1.25;
        ctx.beginPath();
        ctx.moveTo(x, s.top);
        ctx.lineTo(x, s.h - s.bottom);
        ctx.stroke();
        ctx.fillStyle = color;
        const label = `${name} = ${t}`;
        const w = ctx.measureText(label).width;
        const lx = x + 3 + w > s.w - s.right ? x - 3 - w : x + 3;
        ctx.fillText(label, lx, s.h - s.bottom - 28 + i * 13);
      });
      ctx.setLineDash([]);
      ctx.font = '11px system-ui, sans-serif';
      ctx.textAlign = 'left';
      ctx.fillStyle = rgb(COLORS.inspected);
      ctx.textBaseline = 'top';
      ctx.fillText('c(t): corroded cells inspected', s.left + 6, s.top + 4);
      ctx.fillStyle = 'rgb(31, 111, 235)';
      ctx.fillText('m(t): hull cells known', s.left + 6, s.top + 18);
      return canvas;
    }

    draw() {
      const r = this.replay;
      const s = this.size;
      const ctx = this.canvas.getContext('2d');
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.clearRect(0, 0, this.canvas.width, this.canvas.height);
      ctx.drawImage(this.background, 0, 0);
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      const x = this.x(r.t);
      ctx.strokeStyle = '#1d2228';
      ctx.lineWidth = 1.5;
      ctx.beginPath();
      ctx.moveTo(x, s.top);
      ctx.lineTo(x, s.h - s.bottom);
      ctx.stroke();
      const v = r.coverage(r.t);
      for (const [value, color] of [[v.m, 'rgb(31, 111, 235)'], [v.c, rgb(COLORS.inspected)]]) {
        ctx.beginPath();
        ctx.arc(x, this.y(value), 4, 0, 2 * Math.PI);
        ctx.fillStyle = color;
        ctx.fill();
        ctx.strokeStyle = '#fff';
        ctx.lineWidth = 1.5;
        ctx.stroke();
      }
    }
  }

  hv.ProgressChart = ProgressChart;
})(window.hullinspectViewer = window.hullinspectViewer || {});
