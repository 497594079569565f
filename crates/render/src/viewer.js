// cagd-exact interactive viewer: no network, no library. The data (points evaluated exactly,
// converted to f64; exact coordinates as text) is the JSON of the element #scene-data.
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("scene-data").textContent);
  var canvas = document.getElementById("view");
  var ctx = canvas.getContext("2d");
  var tip = document.getElementById("tip");
  var state = { azimuth: data.view.azimuth, elevation: data.view.elevation, zoom: 1 };

  // #azimuth=60&elevation=20&zoom=1.5 sets the view (for links and tests).
  function readHash() {
    var h = window.location.hash.replace(/^#/, "");
    h.split("&").forEach(function (kv) {
      var p = kv.split("=");
      var x = parseFloat(p[1]);
      if (p.length === 2 && isFinite(x) && (p[0] in state)) { state[p[0]] = x; }
    });
  }
  readHash();
  window.addEventListener("hashchange", function () { readHash(); draw(); });

  var toggles = {};
  ["surface", "mesh", "boundary", "curves", "axes"].forEach(function (k) {
    var box = document.getElementById("show-" + k);
    toggles[k] = box;
    if (box) { box.addEventListener("change", draw); }
  });
  function shown(k) { return !toggles[k] || toggles[k].checked; }

  // Bounding box of everything, for the fit and the axes.
  var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  function grow(p) { for (var k = 0; k < 3; k++) { lo[k] = Math.min(lo[k], p[k]); hi[k] = Math.max(hi[k], p[k]); } }
  data.surfaces.forEach(function (s) { s.grid.forEach(function (r) { r.forEach(grow); }); s.net.forEach(function (r) { r.forEach(grow); }); });
  data.curves.forEach(function (c) { c.points.forEach(grow); c.polygon.forEach(grow); });
  var size = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-9);
  var centre = [(lo[0] + hi[0]) / 2, (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2];
  var axes = [0, 1, 2].map(function (k) { var e = [0, 0, 0]; e[k] = Math.max(hi[k], 0) + 0.2 * size; return e; });

  function basis() {
    var a = state.azimuth * Math.PI / 180, e = state.elevation * Math.PI / 180;
    var sa = Math.sin(a), ca = Math.cos(a), se = Math.sin(e), ce = Math.cos(e);
    return [[-sa, ca, 0], [-se * ca, -se * sa, ce], [ce * ca, ce * sa, se]];
  }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
  function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
  function unit(v) { var n = Math.sqrt(dot(v, v)); return n > 0 ? [v[0] / n, v[1] / n, v[2] / n] : null; }
  function hex(c) { return [parseInt(c.substr(1, 2), 16), parseInt(c.substr(3, 2), 16), parseInt(c.substr(5, 2), 16)]; }
  function mix(c, d, t) { return "rgb(" + [0, 1, 2].map(function (k) { return Math.round(c[k] * (1 - t) + d[k] * t); }).join(",") + ")"; }

  var B, scale, hotspots = [];
  function project(p) {
    var q = sub(p, centre);
    return [canvas.width / 2 + scale * dot(q, B[0]), canvas.height / 2 - scale * dot(q, B[1]), dot(q, B[2])];
  }

  function draw() {
    B = basis();
    var radius = 0.5 * Math.sqrt(3) * size;
    scale = state.zoom * 0.92 * Math.min(canvas.width, canvas.height) / (2 * radius);
    ctx.fillStyle = "#ffffff";
    ctx.fillRect(0, 0, canvas.width, canvas.height);
    var light = unit([B[2][0] + 0.6 * B[1][0] - 0.4 * B[0][0], B[2][1] + 0.6 * B[1][1] - 0.4 * B[0][1], B[2][2] + 0.6 * B[1][2] - 0.4 * B[0][2]]);
    var items = [];
    var bias = 0.02 * size * scale;
    if (shown("axes")) {
      var o = project([0, 0, 0]);
      axes.forEach(function (e, k) {
        var p = project(e);
        items.push({ depth: -Infinity, draw: function () {
          ctx.strokeStyle = "#555"; ctx.lineWidth = 1; ctx.beginPath(); ctx.moveTo(o[0], o[1]); ctx.lineTo(p[0], p[1]); ctx.stroke();
          ctx.fillStyle = "#555"; ctx.font = "italic 16px sans-serif"; ctx.fillText(["x", "y", "z"][k], p[0] + 6, p[1] + 4);
        } });
      });
    }
    data.surfaces.forEach(function (s) {
      var g = s.grid.map(function (r) { return r.map(project); });
      var col = hex(s.colour), line = mix(col, [0, 0, 0], 0.55), back = hex(s.back_colour);
      var k = s.sub;
      if (shown("surface")) {
        for (var ci = 0; ci < s.cells[0]; ci++) {
          for (var cj = 0; cj < s.cells[1]; cj++) {
            (function (i0, i1, j0, j1) {
              var ring = [], i, j;
              for (j = j0; j < j1; j++) { ring.push(g[i0][j]); }
              for (i = i0; i < i1; i++) { ring.push(g[i][j1]); }
              for (j = j1; j > j0; j--) { ring.push(g[i1][j]); }
              for (i = i1; i > i0; i--) { ring.push(g[i][j0]); }
              var P = s.grid;
              var n = unit(cross(sub(P[i1][j1], P[i0][j0]), sub(P[i0][j1], P[i1][j0])));
              var fill = mix(col, [0, 0, 0], 0);
              if (n) {
                var base = dot(n, B[2]) >= 0 ? col : back;
                fill = mix(base, [0, 0, 0], 0.5 * (1 - Math.abs(dot(n, light))));
              }
              var depth = (g[i0][j0][2] + g[i0][j1][2] + g[i1][j0][2] + g[i1][j1][2]) / 4 * scale;
              items.push({ depth: depth, draw: function () {
                ctx.beginPath(); ctx.moveTo(ring[0][0], ring[0][1]);
                for (var t = 1; t < ring.length; t++) { ctx.lineTo(ring[t][0], ring[t][1]); }
                ctx.closePath(); ctx.fillStyle = fill; ctx.fill();
                ctx.strokeStyle = line; ctx.lineWidth = 0.7; ctx.stroke();
              } });
            })(ci * k, (ci + 1) * k, cj * k, (cj + 1) * k);
          }
        }
      }
      if (shown("boundary")) {
        var rows = g.length, cols = g[0].length, edges = [g[0], g[rows - 1], g.map(function (r) { return r[0]; }), g.map(function (r) { return r[cols - 1]; })];
        edges.forEach(function (e) { pieces(items, e, k, mix(col, [0, 0, 0], 0.6), 1.8, bias); });
      }
    });
    if (shown("curves")) {
      data.curves.forEach(function (c) { pieces(items, c.points.map(project), 4, c.colour, 2.6, bias); });
    }
    items.sort(function (a, b) { return a.depth - b.depth; });
    items.forEach(function (it) { it.draw(); });

    hotspots = [];
    if (shown("curves")) {
      data.curves.forEach(function (c) {
        var q = c.polygon.map(project);
        ctx.setLineDash([4, 3]); ctx.strokeStyle = c.colour; ctx.lineWidth = 1;
        ctx.beginPath(); q.forEach(function (p, i) { if (i) { ctx.lineTo(p[0], p[1]); } else { ctx.moveTo(p[0], p[1]); } }); ctx.stroke();
        ctx.setLineDash([]);
        q.forEach(function (p, i) {
          ctx.fillStyle = c.colour; ctx.fillRect(p[0] - 2.5, p[1] - 2.5, 5, 5);
          hotspots.push({ x: p[0], y: p[1], text: c.name + ": b" + i + " = " + c.polygon_text[i] + (c.weights_text ? ", w = " + c.weights_text[i] : "") });
        });
        var mid = project(c.points[Math.floor(c.points.length / 2)]);
        ctx.font = "bold 13px sans-serif"; ctx.fillStyle = c.colour; ctx.fillText(c.name, mid[0] + 6, mid[1] - 6);
      });
    }
    if (shown("mesh")) {
      data.surfaces.forEach(function (s) {
        var q = s.net.map(function (r) { return r.map(project); });
        ctx.strokeStyle = s.mesh_colour; ctx.lineWidth = 1.2;
        for (var i = 0; i < q.length; i++) {
          for (var j = 0; j < q[i].length; j++) {
            ctx.beginPath();
            if (j + 1 < q[i].length) { ctx.moveTo(q[i][j][0], q[i][j][1]); ctx.lineTo(q[i][j + 1][0], q[i][j + 1][1]); }
            if (i + 1 < q.length) { ctx.moveTo(q[i][j][0], q[i][j][1]); ctx.lineTo(q[i + 1][j][0], q[i + 1][j][1]); }
            ctx.stroke();
          }
        }
        for (var a = 0; a < q.length; a++) {
          for (var b = 0; b < q[a].length; b++) {
            var p = q[a][b];
            ctx.fillStyle = s.mesh_colour; ctx.beginPath(); ctx.arc(p[0], p[1], 3.5, 0, 2 * Math.PI); ctx.fill();
            hotspots.push({ x: p[0], y: p[1], text: s.name + ": c" + a + "," + b + " = " + s.net_text[a][b] + (s.weights_text ? ", w = " + s.weights_text[a][b] : "") });
          }
        }
      });
    }
    canvas.setAttribute("data-view", state.azimuth + "," + state.elevation + "," + state.zoom);
  }

  function pieces(items, pts, piece, colour, width, bias) {
    for (var start = 0; start + 1 < pts.length; start += piece) {
      (function (run) {
        var depth = run.reduce(function (s, p) { return s + p[2]; }, 0) / run.length * scale + bias;
        items.push({ depth: depth, draw: function () {
          ctx.strokeStyle = colour; ctx.lineWidth = width; ctx.lineJoin = "round"; ctx.lineCap = "round";
          ctx.beginPath(); ctx.moveTo(run[0][0], run[0][1]);
          for (var t = 1; t < run.length; t++) { ctx.lineTo(run[t][0], run[t][1]); }
          ctx.stroke();
        } });
      })(pts.slice(start, Math.min(start + piece, pts.length - 1) + 1));
    }
  }

  // Drag to rotate, wheel to zoom, hover a control point to read it exactly.
  var drag = null;
  canvas.addEventListener("mousedown", function (e) { drag = [e.clientX, e.clientY]; tip.style.display = "none"; });
  window.addEventListener("mouseup", function () { drag = null; });
  window.addEventListener("mousemove", function (e) {
    if (drag) {
      state.azimuth -= 0.5 * (e.clientX - drag[0]);
      state.elevation = Math.max(-89, Math.min(89, state.elevation + 0.5 * (e.clientY - drag[1])));
      drag = [e.clientX, e.clientY];
      draw();
      return;
    }
    var r = canvas.getBoundingClientRect();
    var x = (e.clientX - r.left) * canvas.width / r.width, y = (e.clientY - r.top) * canvas.height / r.height;
    var best = null, bestD = 64;
    hotspots.forEach(function (h) { var d = (h.x - x) * (h.x - x) + (h.y - y) * (h.y - y); if (d < bestD) { bestD = d; best = h; } });
    if (best) {
      tip.textContent = best.text;
      tip.style.display = "block";
      tip.style.left = (e.pageX + 12) + "px";
      tip.style.top = (e.pageY + 12) + "px";
    } else {
      tip.style.display = "none";
    }
  });
  canvas.addEventListener("wheel", function (e) {
    e.preventDefault();
    state.zoom = Math.max(0.1, Math.min(20, state.zoom * Math.exp(-0.001 * e.deltaY)));
    draw();
  }, { passive: false });
  draw();
})();
