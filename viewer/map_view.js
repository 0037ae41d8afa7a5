// The map of the replay viewer, drawn like the paper's Fig. 5: cells on one canvas (one pixel per
// cell, scaled up), everything that moves on a second canvas above it (planner layers, footprints,
// recent paths, plans, targets, UAVs, labels, the hovered cell).
'use strict';

(function (hv) {
  const {FOOTPRINT_FILL, TRUTH_MARK, HOVER_MARK, NO_FLY_MARK, UNREACHABLE_MARK, SEAM_MARK, uavColor,
    layerColor, cellColor} = hv.palette;
  const {LAUNCH_SITE_FILL, GROUND_FILL, AWAY_FILL} = hv.palette;
  const PATH_LENGTH = 40; // steps of recent path drawn behind each UAV
  // On the ground, or flying between its launch site and the hull: not a UAV at work on the hull.
  const offHull = (s) => !s.airborne || s.away > 0;
  // Margins around the cells (CSS px), inside the overlay canvas: axes in metres below and left,
  // room above and right so markers and labels of the outer rows are not cut off.
  const PAD = {top: 18, right: 18, bottom: 34, left: 46};
  const LABEL_FONT = '600 11px system-ui, sans-serif';
  const LABEL_HALO = 1.5; // half the width of the white stroke around label text
  const LABEL_RINGS = 6; // rings of places tried further from a UAV before its label is left out

  class MapView {
    // The margins around the cells, CSS px.
    static get padding() { return PAD; }

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
      const g = this.gridCanvas;
      g.style.width = `${w}px`;
      g.style.height = `${h}px`;
      g.width = Math.round(w * dpr);
      g.height = Math.round(h * dpr);
      // The margins are the stack's padding (a canvas margin would collapse out of the stack).
      g.parentElement.style.padding = `${PAD.top}px ${PAD.right}px ${PAD.bottom}px ${PAD.left}px`;
      const o = this.overlayCanvas;
      const ow = w + PAD.left + PAD.right;
      const oh = h + PAD.top + PAD.bottom;
      o.style.width = `${ow}px`;
      o.style.height = `${oh}px`;
      o.width = Math.round(ow * dpr);
      o.height = Math.round(oh * dpr);
      return w;
    }

    // The cell under a mouse position, or null.
    cellAt(clientX, clientY) {
      const rect = this.gridCanvas.getBoundingClientRect();
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

    cellColor(i) { return cellColor(this.replay, i, this.show.regions); }

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
      ctx.setTransform(1, 0, 0, 1, 0, 0);
      ctx.clearRect(0, 0, this.overlayCanvas.width, this.overlayCanvas.height);
      // Everything below is in CSS px with the origin at the top-left corner of the cells.
      ctx.setTransform(this.dpr, 0, 0, this.dpr, PAD.left * this.dpr, PAD.top * this.dpr);
      this.drawAxes(ctx);
      const cp = this.cellPx;
      const t = r.t;
      if (this.show.truth) this.drawTruth(ctx, t);
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
      this.drawSeam(ctx);
      const states = [];
      for (let k = 0; k < r.uavCount; ++k) states.push(r.uavState(t, k));
      if (this.show.footprints) {
        const fp = r.trace.footprint;
        states.forEach((s, k) => {
          if (!s.active || offHull(s)) return; // away from the hull a UAV senses nothing
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
      this.drawLaunchSites(ctx);
      states.forEach((s, k) => (offHull(s) ? this.drawOffHull(ctx, s, k) : this.drawUav(ctx, s, k)));
      if (this.show.labels) this.drawLabels(ctx, states, notes); else this.labelBoxes = [];
      if (this.hover) {
        // A yellow ring and a cross-hair along the row and the column: unlike targets (white
        // squares with a UAV's colour).
        const {x, y} = this.hover;
        const px = x * cp;
        const py = (r.H - 1 - y) * cp;
        ctx.strokeStyle = 'rgba(0, 0, 0, 0.45)';
        ctx.lineWidth = 1;
        ctx.setLineDash([2, 3]);
        ctx.beginPath();
        ctx.moveTo(0, py + cp / 2);
        ctx.lineTo(px - 3, py + cp / 2);
        ctx.moveTo(px + cp + 3, py + cp / 2);
        ctx.lineTo(r.W * cp, py + cp / 2);
        ctx.moveTo(px + cp / 2, 0);
        ctx.lineTo(px + cp / 2, py - 3);
        ctx.moveTo(px + cp / 2, py + cp + 3);
        ctx.lineTo(px + cp / 2, r.H * cp);
        ctx.stroke();
        ctx.setLineDash([]);
        ctx.lineWidth = 2.5;
        ctx.strokeStyle = '#000';
        ctx.strokeRect(px - 2.5, py - 2.5, cp + 5, cp + 5);
        ctx.lineWidth = 1.5;
        ctx.strokeStyle = HOVER_MARK;
        ctx.strokeRect(px - 2.5, py - 2.5, cp + 5, cp + 5);
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
        ctx.strokeStyle = nf ? NO_FLY_MARK : UNREACHABLE_MARK[un];
        ctx.stroke();
      }
    }

    // Undetected corrosion ("show truth"): a red dot in every corroded cell nobody has seen as
    // corroded yet (M is 0 there); the planners never see it.
    drawTruth(ctx, t) {
      const r = this.replay;
      const cp = this.cellPx;
      const d = Math.max(2, cp * 0.5);
      ctx.fillStyle = TRUTH_MARK;
      for (let i = 0; i < r.W * r.H; ++i) {
        if (r.truth[i] !== 1 || r.map[i] !== 0) continue;
        const x = i % r.W;
        const y = (i - x) / r.W;
        ctx.fillRect((x + 0.5) * cp - d / 2, (r.H - 1 - y + 0.5) * cp - d / 2, d, d);
      }
    }

    // Axes in metres: x along the hull from the stern (left) to the bow (right), y upward.
    drawAxes(ctx) {
      const r = this.replay;
      const m = r.trace.grid.cell_size_m || 1;
      const unit = r.trace.grid.cell_size_m ? 'm' : 'cells';
      const cp = this.cellPx;
      const w = r.W * cp;
      const h = r.H * cp;
      const step = (extentCells, spacePx) => {
        const metres = extentCells * m;
        for (const s of [0.5, 1, 2, 5, 10, 20, 25, 50, 100, 200, 500, 1000]) {
          if ((s / metres) * spacePx >= 55) return s;
        }
        return metres;
      };
      // What is written where (overlay-canvas CSS px, the anchor of each text) is kept in
      // `axisTexts` for the browser test.
      this.axisTexts = [];
      const write = (kind, text, x, y, at = [x, y]) => {
        ctx.fillText(text, x, y);
        this.axisTexts.push({kind, text, x: at[0] + PAD.left, y: at[1] + PAD.top});
      };
      ctx.font = '11px system-ui, sans-serif';
      ctx.fillStyle = '#333';
      ctx.strokeStyle = '#666';
      ctx.lineWidth = 1;
      ctx.beginPath();
      ctx.moveTo(0, h + 0.5);
      ctx.lineTo(w, h + 0.5);
      ctx.moveTo(-0.5, 0);
      ctx.lineTo(-0.5, h);
      const sx = step(r.W, w);
      ctx.textAlign = 'center';
      ctx.textBaseline = 'top';
      for (let v = 0; v <= r.W * m + 1e-9; v += sx) {
        const x = (v / m) * cp;
        ctx.moveTo(x, h);
        ctx.lineTo(x, h + 4);
        write('x-tick', `${Number(v.toFixed(2))}`, Math.min(Math.max(x, 8), w - 8), h + 5, [x, h]);
      }
      const sy = step(r.H, h);
      ctx.textAlign = 'right';
      ctx.textBaseline = 'middle';
      for (let v = 0; v <= r.H * m + 1e-9; v += sy) {
        const y = h - (v / m) * cp;
        ctx.moveTo(-4, y);
        ctx.lineTo(0, y);
        write('y-tick', `${Number(v.toFixed(2))}`, -6, Math.min(Math.max(y, 6), h - 4), [0, y]);
      }
      ctx.stroke();
      ctx.font = '600 11px system-ui, sans-serif';
      ctx.textBaseline = 'top';
      ctx.textAlign = 'left';
      write('stern', '◀ stern', 0, h + 19);
      ctx.textAlign = 'right';
      write('bow', 'bow ▶', w, h + 19);
      ctx.textAlign = 'center';
      write('x-title', `x (${unit}, along the hull)`, w / 2, h + 19);
      ctx.save();
      ctx.translate(-34, h / 2);
      ctx.rotate(-Math.PI / 2);
      ctx.textBaseline = 'middle';
      write('y-title', `y (${unit})`, 0, 0, [-34, h / 2]);
      ctx.restore();
      ctx.textAlign = 'left';
    }

    // "k mode" beside each UAV where it covers neither a UAV nor another label and stays on the
    // canvas; else the UAV's number alone beside it; else the number further out, joined to its UAV
    // by a thin line. The ink boxes placed (overlay-canvas CSS px, stroke halo included) are kept in
    // `labelBoxes` with the markers' boxes in `markerBoxes`: the browser test checks them.
    drawLabels(ctx, states, notes) {
      ctx.font = LABEL_FONT;
      ctx.textBaseline = 'middle';
      ctx.textAlign = 'left';
      ctx.lineJoin = 'round';
      const rad = this.markerRadius();
      // Labels may use the margins above and to the right of the cells (the axes are below and to
      // the left), never leave the canvas.
      const minX = 0;
      const maxX = this.replay.W * this.cellPx + PAD.right - 1;
      const minY = -PAD.top + 1;
      const maxY = this.replay.H * this.cellPx;
      const d = rad + 2; // half the side of the box a marker keeps free (its outer ring: rad + 1.75)
      const markers = states.map((s) => ({x: this.cx(s.x) - d, y: this.cy(s.y) - d, w: 2 * d, h: 2 * d}));
      const placed = markers.slice(); // markers first: a label covers no UAV
      const overlaps = (b) => placed.some((p) => b.x < p.x + p.w && p.x < b.x + b.w && b.y < p.y + p.h && p.y < b.y + b.h);
      const fits = (b) => b.x >= minX && b.x + b.w <= maxX && b.y >= minY && b.y + b.h <= maxY && !overlaps(b);
      // Ink box of `text` (halo included) at the candidate places around (x, y): beside the marker,
      // then (ring > 0) further out in 16 directions.
      const candidates = (text, x, y, ring) => {
        const m = ctx.measureText(text);
        const w = m.actualBoundingBoxLeft + m.actualBoundingBoxRight + 2 * LABEL_HALO;
        const h = m.actualBoundingBoxAscent + m.actualBoundingBoxDescent + 2 * LABEL_HALO;
        const box = (bx, by) => ({x: bx, y: by, w, h, text, m});
        if (ring === 0) { // touching the marker's box: right, left, the corners, above, below
          return [
            [x + d, y - h / 2], [x - d - w, y - h / 2], [x + d, y - d - h], [x + d, y + d],
            [x - d - w, y - d - h], [x - d - w, y + d], [x - w / 2, y - d - h], [x - w / 2, y + d],
            [x + d, y - d - 2 * h], [x - d - w, y + d + h],
          ].map(([bx, by]) => box(bx, by));
        }
        const out = [];
        for (let a = 0; a < 16; ++a) {
          const angle = (a * Math.PI) / 8;
          const cx = x + Math.cos(angle) * (d + ring * (h + 1) + w / 2);
          const cy = y - Math.sin(angle) * (d + ring * (h + 1) + h / 2);
          out.push(box(cx - w / 2, cy - h / 2));
        }
        return out;
      };
      this.labelBoxes = [];
      this.markerBoxes = markers.map((b) => ({x: b.x + PAD.left, y: b.y + PAD.top, w: b.w, h: b.h}));
      states.forEach((s, k) => {
        const a = notes[k];
        const x = this.cx(s.x);
        const y = this.cy(s.y);
        const full = a && a.mode ? `${k} ${a.mode}` : `${k}`;
        let box = candidates(full, x, y, 0).find(fits) || candidates(`${k}`, x, y, 0).find(fits);
        let leader = false;
        for (let ring = 1; !box && ring <= LABEL_RINGS; ++ring) {
          box = candidates(`${k}`, x, y, ring).find(fits);
          leader = true;
        }
        if (!box) return; // no room anywhere near: the UAV table still names it
        placed.push(box);
        const tx = box.x + LABEL_HALO + box.m.actualBoundingBoxLeft;
        const ty = box.y + LABEL_HALO + box.m.actualBoundingBoxAscent;
        if (leader) {
          const lx = Math.max(box.x, Math.min(box.x + box.w, x));
          const ly = Math.max(box.y, Math.min(box.y + box.h, y));
          ctx.strokeStyle = uavColor(k);
          ctx.lineWidth = 1;
          ctx.beginPath();
          ctx.moveTo(x + ((lx - x) * rad) / Math.hypot(lx - x, ly - y), y + ((ly - y) * rad) / Math.hypot(lx - x, ly - y));
          ctx.lineTo(lx, ly);
          ctx.stroke();
        }
        ctx.strokeStyle = 'rgba(255, 255, 255, 0.9)';
        ctx.lineWidth = 2 * LABEL_HALO;
        ctx.strokeText(box.text, tx, ty);
        ctx.fillStyle = uavColor(k);
        ctx.fillText(box.text, tx, ty);
        this.labelBoxes.push({k, text: box.text, leader, x: box.x + PAD.left, y: box.y + PAD.top, w: box.w, h: box.h});
      });
    }

    markerRadius() { return Math.max(4.5, Math.min(10, this.cellPx * 0.9)); }

    // The last PATH_LENGTH steps: solid where the UAV was at z = 1, dashed at z = 2, older steps
    // fainter. Segments are batched into one path per (age bucket, plane) to keep strokes few.
    drawPaths(ctx, t) {
      const r = this.replay;
      const from = Math.max(0, t - PATH_LENGTH);
      const buckets = 4;
      const seam = this.hasSeam() && r.W > 2;
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
              if (seam && a.y === c.y && Math.abs(a.x - c.x) === r.W - 1) {
                // Across the seam: out through one edge of the grid and in through the other.
                const out = a.x === 0 ? 0 : r.W * this.cellPx;
                ctx.moveTo(this.cx(a.x), this.cy(a.y));
                ctx.lineTo(out, this.cy(a.y));
                ctx.moveTo(r.W * this.cellPx - out, this.cy(c.y));
              } else {
                ctx.moveTo(this.cx(a.x), this.cy(a.y));
              }
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

    // True when the trace's grid closes on itself: column 0 and column W − 1 meet at the seam.
    hasSeam() {
      const frame = this.replay.trace.ship_frame;
      return Boolean(frame && frame.seam);
    }

    // The seam: both edges of the grid dashed, as they are one line on the hull. Their x (overlay
    // CSS px) are kept in `seamEdges` for the browser test (empty without a seam).
    drawSeam(ctx) {
      this.seamEdges = [];
      if (!this.hasSeam()) return;
      const r = this.replay;
      const h = r.H * this.cellPx;
      ctx.strokeStyle = SEAM_MARK;
      ctx.lineWidth = 2;
      ctx.setLineDash([6, 4]);
      ctx.beginPath();
      for (const x of [1, r.W * this.cellPx - 1]) {
        ctx.moveTo(x, 0);
        ctx.lineTo(x, h);
        this.seamEdges.push(x + PAD.left);
      }
      ctx.stroke();
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

    // Launch sites: a light pad with a dark outline under the UAVs that take off there.
    drawLaunchSites(ctx) {
      const cp = this.cellPx;
      const r = this.replay;
      for (const [x, y] of r.launchSites) {
        const pad = Math.max(1, cp * 0.2);
        ctx.fillStyle = LAUNCH_SITE_FILL;
        ctx.fillRect(x * cp - pad, (r.H - 1 - y) * cp - pad, cp + 2 * pad, cp + 2 * pad);
        ctx.strokeStyle = '#111';
        ctx.lineWidth = 1.5;
        ctx.strokeRect(x * cp - pad, (r.H - 1 - y) * cp - pad, cp + 2 * pad, cp + 2 * pad);
      }
    }

    // A UAV away from the hull: on the ground at its site a dark triangle, flying out or home a
    // dark diamond, both outlined in its colour; never the round marker of a UAV on the hull.
    drawOffHull(ctx, s, k) {
      const x = this.cx(s.x);
      const y = this.cy(s.y);
      const rad = this.markerRadius();
      ctx.beginPath();
      if (!s.airborne) {
        ctx.moveTo(x, y - rad);
        ctx.lineTo(x + rad, y + rad * 0.8);
        ctx.lineTo(x - rad, y + rad * 0.8);
      } else {
        ctx.moveTo(x, y - rad);
        ctx.lineTo(x + rad, y);
        ctx.lineTo(x, y + rad);
        ctx.lineTo(x - rad, y);
      }
      ctx.closePath();
      ctx.fillStyle = s.airborne ? AWAY_FILL : GROUND_FILL;
      ctx.fill();
      ctx.lineWidth = 2;
      ctx.strokeStyle = s.active ? uavColor(k) : '#777';
      ctx.stroke();
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
