// The map of the replay viewer, drawn like the paper's Fig. 5: cells on one canvas (one pixel per
// cell, scaled up), everything that moves on a second canvas above it (planner layers, footprints,
// recent paths, plans, targets, UAVs, labels, the hovered cell).
'use strict';

(function (hv) {
  const {COLORS, FOOTPRINT_FILL, regionColor, regionTint, uavColor, layerColor} = hv.palette;
  const PATH_LENGTH = 40; // steps of recent path drawn behind each UAV

  class MapView {
    // `show` holds the switches of the "show" row (footprints, paths, plans, targets, layers,
    // labels, regions); the viewer owns it and changes it.
    constructor(replay, gridCanvas, overlayCanvas, show) {
      this.replay = replay;
      this.gridCanvas = gridCanvas;
      this.overlayCanvas = overlayCanvas;
      this.show = show;
      this.hover = null; // the cell under the mouse, {x, y}
      this.cellPx = 5;
      this.dpr = 1;
      this.cellImage = new ImageData(replay.W, replay.H);
      this.cellCanvas = document.createElement('canvas');
      this.cellCanvas.width = replay.W;
      this.cellCanvas.height = replay.H;
      this.regionBoundary = replay.owner ? this.buildRegionBoundary() : null;
    }

    // Sizes both canvases for `cellPx` CSS pixels per cell (a fraction when fitting the width);
    // returns the CSS width.
    layout(cellPx, dpr) {
      const r = this.replay;
      const w = Math.floor(r.W * cellPx);
      this.cellPx = w / r.W;
      this.dpr = dpr;
      const h = Math.round(r.H * this.cellPx);
      for (const c of [this.gridCanvas, this.overlayCanvas]) {
        c.style.width = `${w}px`;
        c.style.height = `${h}px`;
        c.width = Math.round(w * dpr);
        c.height = Math.round(h * dpr);
      }
      return w;
    }

    // The cell under a mouse position, or null.
    cellAt(clientX, clientY) {
      const rect = this.overlayCanvas.getBoundingClientRect();
      const x = Math.floor((clientX - rect.left) / this.cellPx);
      const y = this.replay.H - 1 - Math.floor((clientY - rect.top) / this.cellPx);
      if (x < 0 || x >= this.replay.W || y < 0 || y >= this.replay.H) return null;
      return {x, y};
    }

    draw() {
      this.drawCells();
      this.drawOverlay();
    }

    // Region boundaries as one path in cell units (y down), built once.
    buildRegionBoundary() {
      const {W, H, owner} = this.replay;
      const segments = [];
      const at = (x, y) => owner[y * W + x];
      for (let y = 0; y < H; ++y) {
        for (let x = 0; x < W; ++x) {
          const o = at(x, y);
          if (o < 0) continue;
          const row = H - 1 - y; // canvas row of this cell
          // Edges towards a different, assigned region (each shared edge once: right and up).
          if (x + 1 < W && at(x + 1, y) >= 0 && at(x + 1, y) !== o) segments.push([x + 1, row, x + 1, row + 1]);
          if (y + 1 < H && at(x, y + 1) >= 0 && at(x, y + 1) !== o) segments.push([x, row, x + 1, row]);
        }
      }
      return segments;
    }

    cellColor(i) {
      const v = this.replay.map[i];
      if (v < 0) return COLORS.nonHull;
      if (v === 2) return COLORS.corrosion;
      if (v === 3) return COLORS.inspected;
      const o = this.replay.owner && this.show.regions ? this.replay.owner[i] : -1;
      if (o >= 0) return v === 0 ? regionColor(o) : regionTint(o);
      return v === 0 ? COLORS.unknown : COLORS.clean;
    }

    drawCells() {
      const {W, H} = this.replay;
      const data = this.cellImage.data;
      for (let y = 0; y < H; ++y) {
        let p = (H - 1 - y) * W * 4;
        for (let x = 0; x < W; ++x, p += 4) {
          const c = this.cellColor(y * W + x);
          data[p] = c[0];
          data[p + 1] = c[1];
          data[p + 2] = c[2];
          data[p + 3] = 255;
        }
      }
      this.cellCanvas.getContext('2d').putImageData(this.cellImage, 0, 0);
      const ctx = this.gridCanvas.getContext('2d');
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.imageSmoothingEnabled = false;
      ctx.drawImage(this.cellCanvas, 0, 0, this.gridCanvas.width, this.gridCanvas.height);
      if (this.regionBoundary && this.show.regions) {
        const s = this.cellPx * this.dpr;
        ctx.strokeStyle = 'rgba(17, 17, 17, 0.8)';
        ctx.lineWidth = Math.max(1, Math.round(this.dpr));
        ctx.beginPath();
        for (const [x0, y0, x1, y1] of this.regionBoundary) {
          ctx.moveTo(x0 * s, y0 * s);
          ctx.lineTo(x1 * s, y1 * s);
        }
        ctx.stroke();
      }
    }

    // Canvas coordinates (CSS px) of a cell's centre; y = 0 is the bottom row.
    cx(x) { return (x + 0.5) * this.cellPx; }
    cy(y) { return (this.replay.H - 1 - y + 0.5) * this.cellPx; }

    drawOverlay() {
      const r = this.replay;
      const ctx = this.overlayCanvas.getContext('2d');
      ctx.setTransform(this.dpr, 0, 0, this.dpr, 0, 0);
      ctx.clearRect(0, 0, r.W * this.cellPx, r.H * this.cellPx);
      const cp = this.cellPx;
      const t = r.t;
      if (this.show.layers) {
        r.layerNames.forEach((name, i) => {
          ctx.fillStyle = layerColor(name, i);
          for (const c of r.layer(name, t)) {
            const x = c % r.W;
            const y = (c - x) / r.W;
            ctx.fillRect(x * cp, (r.H - 1 - y) * cp, cp, cp);
          }
        });
      }
      this.drawNoFly(ctx);
      const states = [];
      for (let k = 0; k < r.uavCount; ++k) states.push(r.uavState(t, k));
      if (this.show.footprints) {
        const fp = r.trace.footprint;
        states.forEach((s, k) => {
          if (!s.active) return;
          const half = ((s.z === 1 ? fp[0] : fp[1]) - 1) / 2;
          const x0 = Math.max(0, s.x - half) * cp;
          const x1 = Math.min(r.W, s.x + half + 1) * cp;
          const yTop = (r.H - 1 - Math.min(r.H - 1, s.y + half)) * cp;
          const yBottom = (r.H - Math.max(0, s.y - half)) * cp;
          ctx.setLineDash(s.transit > 0 ? [3, 3] : []);
          if (s.transit === 0) { // a UAV changing plane does not sense
            ctx.fillStyle = FOOTPRINT_FILL;
            ctx.fillRect(x0, yTop, x1 - x0, yBottom - yTop);
          }
          ctx.strokeStyle = uavColor(k);
          ctx.lineWidth = 1.5;
          ctx.strokeRect(x0 + 0.75, yTop + 0.75, x1 - x0 - 1.5, yBottom - yTop - 1.5);
        });
        ctx.setLineDash([]);
      }
      if (this.show.paths) this.drawPaths(ctx, t);
      const notes = [];
      for (let k = 0; k < r.uavCount; ++k) notes.push(r.annotation(k, t));
      if (this.show.plans) {
        notes.forEach((a, k) => { if (a && a.plan && a.plan.length) this.drawPlan(ctx, states[k], a.plan, k); });
      }
      if (this.show.targets) {
        notes.forEach((a, k) => {
          if (!a || !a.target) return;
          const [x, y] = a.target;
          const px = x * cp;
          const py = (r.H - 1 - y) * cp;
          const pad = Math.max(1, cp * 0.15);
          ctx.fillStyle = '#ffffff';
          ctx.fillRect(px - pad, py - pad, cp + 2 * pad, cp + 2 * pad);
          ctx.strokeStyle = uavColor(k);
          ctx.lineWidth = 2;
          ctx.strokeRect(px - pad, py - pad, cp + 2 * pad, cp + 2 * pad);
        });
      }
      states.forEach((s, k) => this.drawUav(ctx, s, k));
      if (this.show.labels) this.drawLabels(ctx, states, notes);
      if (this.hover) {
        const {x, y} = this.hover;
        ctx.lineWidth = 1.5;
        ctx.strokeStyle = '#000';
        ctx.strokeRect(x * cp - 1, (r.H - 1 - y) * cp - 1, cp + 2, cp + 2);
        ctx.strokeStyle = '#fff';
        ctx.strokeRect(x * cp - 2.5, (r.H - 1 - y) * cp - 2.5, cp + 5, cp + 5);
      }
    }

    // No-fly positions hatched (black diagonals), unreachable hull cells cross-hatched (grey: seen
    // only from z = 2; dark: never seen).
    drawNoFly(ctx) {
      const r = this.replay;
      if (!r.noFly && !r.unreachable) return;
      const cp = this.cellPx;
      ctx.lineWidth = 1;
      for (let i = 0; i < r.W * r.H; ++i) {
        const nf = r.noFly ? r.noFly[i] : 0;
        const un = r.unreachable ? r.unreachable[i] : 0;
        if (!nf && !un) continue;
        const x = (i % r.W) * cp;
        const y = (r.H - 1 - Math.floor(i / r.W)) * cp;
        ctx.beginPath();
        if (nf) {
          ctx.moveTo(x, y + cp);
          ctx.lineTo(x + cp, y);
        }
        if (un) {
          ctx.moveTo(x, y);
          ctx.lineTo(x + cp, y + cp);
        }
        ctx.strokeStyle = nf ? '#111' : (un === 2 ? '#444' : '#999');
        ctx.stroke();
      }
    }

    // "k mode" beside each UAV, moved to another corner of the marker when it would cover a label
    // already placed.
    drawLabels(ctx, states, notes) {
      ctx.font = '600 11px system-ui, sans-serif';
      ctx.textBaseline = 'middle';
      ctx.lineJoin = 'round';
      const rad = this.markerRadius();
      const width = this.replay.W * this.cellPx;
      const height = this.replay.H * this.cellPx;
      const placed = [];
      const overlaps = (b) => placed.some((p) => b.x < p.x + p.w && p.x < b.x + b.w && b.y < p.y + p.h && p.y < b.y + b.h);
      states.forEach((s, k) => {
        const a = notes[k];
        const text = a && a.mode ? `${k} ${a.mode}` : `${k}`;
        const w = ctx.measureText(text).width + 2;
        const h = 12;
        const x = this.cx(s.x);
        const y = this.cy(s.y);
        const candidates = [
          [x + rad, y - rad - h], [x + rad, y + rad], [x - rad - w, y - rad - h], [x - rad - w, y + rad],
          [x + rad + 1, y - h / 2], [x - rad - w - 1, y - h / 2],
        ].map(([bx, by]) => ({x: Math.max(0, Math.min(width - w, bx)), y: Math.max(0, Math.min(height - h, by)), w, h}));
        const box = candidates.find((b) => !overlaps(b)) || candidates[0];
        placed.push(box);
        ctx.strokeStyle = 'rgba(255, 255, 255, 0.9)';
        ctx.lineWidth = 3;
        ctx.strokeText(text, box.x + 1, box.y + h / 2);
        ctx.fillStyle = uavColor(k);
        ctx.fillText(text, box.x + 1, box.y + h / 2);
      });
    }

    markerRadius() { return Math.max(4.5, Math.min(10, this.cellPx * 0.9)); }

    // The last PATH_LENGTH steps: solid where the UAV was at z = 1, dashed at z = 2, older steps
    // fainter. Segments are batched into one path per (age bucket, plane) to keep strokes few.
    drawPaths(ctx, t) {
      const r = this.replay;
      const from = Math.max(0, t - PATH_LENGTH);
      const buckets = 4;
      ctx.lineCap = 'round';
      for (let k = 0; k < r.uavCount; ++k) {
        ctx.strokeStyle = uavColor(k);
        for (let b = 0; b < buckets; ++b) {
          for (const closeUp of [false, true]) {
            ctx.beginPath();
            let any = false;
            for (let i = from; i < t; ++i) {
              if (Math.min(buckets - 1, Math.floor(((i - from) * buckets) / (t - from))) !== b) continue;
              const a = r.uavState(i, k);
              const c = r.uavState(i + 1, k);
              if (a.x === c.x && a.y === c.y) continue;
              if ((a.z === 1 && a.transit === 0 && c.z === 1) !== closeUp) continue;
              ctx.moveTo(this.cx(a.x), this.cy(a.y));
              ctx.lineTo(this.cx(c.x), this.cy(c.y));
              any = true;
            }
            if (!any) continue;
            ctx.globalAlpha = 0.3 + (0.7 * (b + 1)) / buckets;
            ctx.lineWidth = closeUp ? 2.5 : 1.5;
            ctx.setLineDash(closeUp ? [] : [3, 2]);
            ctx.stroke();
          }
        }
      }
      ctx.globalAlpha = 1;
      ctx.setLineDash([]);
    }

    // Waypoints joined the way UAVs fly between them (along x first, then along y).
    drawPlan(ctx, s, plan, k) {
      // Solid and thin: a dashed pattern over long plans costs more than the rest of the frame.
      ctx.strokeStyle = uavColor(k);
      ctx.globalAlpha = 0.6;
      ctx.lineWidth = 1;
      ctx.beginPath();
      let x = s.x;
      let y = s.y;
      ctx.moveTo(this.cx(x), this.cy(y));
      for (const [wx, wy] of plan) {
        ctx.lineTo(this.cx(wx), this.cy(y));
        ctx.lineTo(this.cx(wx), this.cy(wy));
        x = wx;
        y = wy;
      }
      ctx.stroke();
      ctx.fillStyle = uavColor(k);
      const d = Math.max(2, this.cellPx * 0.4);
      for (const [wx, wy] of plan) ctx.fillRect(this.cx(wx) - d / 2, this.cy(wy) - d / 2, d, d);
      ctx.globalAlpha = 1;
    }

    drawUav(ctx, s, k) {
      const x = this.cx(s.x);
      const y = this.cy(s.y);
      const rad = this.markerRadius();
      const color = s.active ? uavColor(k) : '#777';
      ctx.beginPath();
      ctx.arc(x, y, rad, 0, 2 * Math.PI);
      if (!s.active) {
        ctx.fillStyle = '#bbb';
      } else if (s.transit > 0) {
        const g = ctx.createLinearGradient(x - rad, 0, x + rad, 0);
        g.addColorStop(0.5, color);
        g.addColorStop(0.5, '#fff');
        ctx.fillStyle = g;
      } else {
        ctx.fillStyle = s.z === 1 ? color : '#fff';
      }
      ctx.fill();
      ctx.lineWidth = s.z === 1 && s.transit === 0 ? 1.5 : 2.5;
      ctx.strokeStyle = s.z === 1 && s.transit === 0 && s.active ? '#fff' : color;
      ctx.stroke();
      if (s.z === 1 && s.transit === 0 && s.active) {
        ctx.beginPath();
        ctx.arc(x, y, rad + 1.25, 0, 2 * Math.PI);
        ctx.lineWidth = 1;
        ctx.strokeStyle = color;
        ctx.stroke();
      }
      if (!s.active) {
        ctx.strokeStyle = '#333';
        ctx.lineWidth = 1.5;
        ctx.beginPath();
        ctx.moveTo(x - rad * 0.6, y - rad * 0.6);
        ctx.lineTo(x + rad * 0.6, y + rad * 0.6);
        ctx.moveTo(x + rad * 0.6, y - rad * 0.6);
        ctx.lineTo(x - rad * 0.6, y + rad * 0.6);
        ctx.stroke();
      }
    }
  }

  hv.MapView = MapView;
})(window.hullinspectViewer = window.hullinspectViewer || {});
