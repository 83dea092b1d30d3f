/*
 * gen-rapid preview viewer: plain WebGL 1, no library, nothing loaded from anywhere.
 *
 * How it works
 * - The scene (JSON in the script element "scene", written by src/preview/mod.rs; its fields are
 *   documented on `Scene` there) is in the cell frame: z up, millimetres, seconds,
 *   quaternions [w, x, y, z]. Obstacles are axis-aligned boxes; every robot or tool shape is
 *   defined in its own frame, and each keyframe gives every shape frame's pose and the TCP.
 * - No kinematics here. At time t the viewer finds the two keyframes around t and
 *   interpolates each pose: position linearly, orientation by normalised linear interpolation
 *   of the quaternions (nlerp; for the dense keyframes Rust writes it is indistinguishable
 *   from slerp).
 * - Three unit meshes (box [0,1]^3, cylinder of radius 1 along z from 0 to 1, sphere of
 *   radius 1) are placed by model matrices. One shader lights them (two fixed lights in the
 *   cell frame plus ambient, both faces lit); a flat shader draws lines (floor grid, cell
 *   axes, the base frame's x (long) and y axes, box edges, TCP trace, the clearance segment,
 *   the unjoined points of a failure). The TCP trace is drawn move by move in the colour of
 *   the move's kind (scene.moves): air moves, seams (MoveL / MoveC) and approach and retract
 *   lines; along a process move the keyframes follow the line or arc the controller runs.
 * - A waypoint with actions (scene.waypoints[i].actions) gets a marker and a label listing
 *   them as the module writes them (SetDO doWeld, 1; WaitTime 0.300).
 * - Draw order: opaque meshes, lines, then the translucent boxes back to front with depth
 *   writes off (back faces, then front faces).
 * - Text (waypoint and obstacle names, the clearance, failed points) is HTML laid over the
 *   canvas, at the projection of its 3D anchor, moved every frame; a point's label that would
 *   cover another point's (points at the same place) moves down below it.
 * - Orbit camera about the centre of the robot's shapes over the whole motion, the TCP trace and
 *   the points (not the boxes: a large floor or fence may reach out of the view), first seen
 *   from the robot's right
 *   (relative to its base yaw), a little behind and above it: drag rotates, wheel zooms,
 *   right- or shift-drag pans,
 *   double-click resets; space plays or pauses.
 * - The first frame is drawn synchronously while the page loads; then <body> gets
 *   data-rendered="1" (errors go to data-errors, see the hook in the page's head).
 *   "#t=1.5" in the address starts paused at 1.5 s (for screenshots); otherwise it plays.
 */
(function () {
  "use strict";

  // ---- colours (r, g, b, a in 0..1) ----
  var COLOURS = {
    background: [0.957, 0.965, 0.973, 1],
    obstacle: [0.33, 0.53, 0.9, 0.2],
    obstacleEdge: [0.2, 0.33, 0.52, 1],
    hitEdge: [0.8, 0.08, 0.16, 1],
    link: [0.93, 0.5, 0.1, 1],
    tool: [0.1, 0.62, 0.55, 1],
    trace: [0.5, 0.2, 0.72, 1],
    seam: [0.95, 0.1, 0.6, 1],
    line: [0.0, 0.42, 0.95, 1],
    action: [0.95, 0.7, 0.05, 1],
    cellPoint: [0.12, 0.15, 0.2, 1],
    via: [0.45, 0.5, 0.56, 1],
    clearance: [0.85, 0.05, 0.15, 1],
    failed: [0.85, 0.05, 0.15, 1],
    grid: [0.82, 0.85, 0.88, 1],
    gridMajor: [0.68, 0.72, 0.77, 1],
    axisX: [0.85, 0.2, 0.2, 1],
    axisY: [0.2, 0.65, 0.25, 1],
    axisZ: [0.2, 0.35, 0.85, 1]
  };
  var FOV_Y = 40 * Math.PI / 180;

  var scene = JSON.parse(document.getElementById("scene").textContent);

  // ---- panels (text only: filled before WebGL is needed, so they show without it) ----
  document.title = scene.title || document.title;
  document.getElementById("title").textContent = scene.title;
  var facts = ["module " + scene.module, "cell " + scene.cell_file];
  var cellCount = scene.waypoints.filter(function (w) { return w.kind === "cell"; }).length;
  if (scene.waypoints.length) {
    facts.push(scene.waypoints.length + " waypoints (" + cellCount + " cell points), " +
      Math.max(0, scene.waypoints.length - 1) + " moves");
  }
  if (scene.total_time_s != null) {
    facts.push("estimated time " + scene.total_time_s.toFixed(2) + " s");
  }
  if (scene.clearance) {
    facts.push("min clearance " + scene.clearance.distance_mm.toFixed(1) + " mm");
  }
  document.getElementById("facts").textContent = facts.join(" \u00b7 ");
  var legend = document.getElementById("legend");
  var moves = scene.moves || [];
  // The colour of the TCP trace along a move, by its kind.
  function moveColour(kind) {
    if (kind === "linear" || kind === "circular") return COLOURS.seam;
    if (kind === "approach" || kind === "retract") return COLOURS.line;
    return COLOURS.trace;
  }
  function some(kinds) {
    return moves.some(function (m) { return kinds.indexOf(m.kind) >= 0; });
  }
  var withActions = scene.waypoints.filter(function (w) { return w.actions && w.actions.length; });
  var entries = [["obstacle", COLOURS.obstacle], ["link", COLOURS.link], ["tool", COLOURS.tool],
    [moves.length && moves.some(function (m) { return m.kind !== "joint"; }) ?
      "air move (TCP)" : "TCP trace", COLOURS.trace]];
  if (some(["linear", "circular"])) entries.push(["seam (MoveL / MoveC)", COLOURS.seam]);
  if (some(["approach", "retract"])) entries.push(["approach / retract line", COLOURS.line]);
  if (withActions.length) entries.push(["actions", COLOURS.action]);
  entries.push(["clearance", COLOURS.clearance]);
  entries.forEach(function (e) {
    var s = document.createElement("span");
    s.textContent = e[0];
    var rgb = e[1].slice(0, 3).map(function (c) { return Math.round(c * 255); });
    s.style.setProperty("--c", "rgb(" + rgb.join(",") + ")");
    legend.appendChild(s);
  });
  if (scene.failure) {
    var box = document.getElementById("failure");
    box.hidden = false;
    box.textContent = "Planning failed\n\n" + scene.failure.message;
  }

  var canvas = document.getElementById("view");
  // An opaque canvas (alpha: false): translucent boxes must not make the page show through.
  // preserveDrawingBuffer keeps the last frame for screenshots.
  var gl = canvas.getContext("webgl",
    { alpha: false, antialias: true, preserveDrawingBuffer: true }) ||
    canvas.getContext("experimental-webgl", { alpha: false, preserveDrawingBuffer: true });
  if (!gl) {
    throw new Error("WebGL is not available in this browser; the preview needs it " +
      "(the text above still holds)");
  }

  // ---- small matrix library: 4x4 column-major Float32Array ----
  function mat4() { var m = new Float32Array(16); m[0] = m[5] = m[10] = m[15] = 1; return m; }
  function mul(a, b) {
    var o = new Float32Array(16);
    for (var c = 0; c < 4; c++) {
      for (var r = 0; r < 4; r++) {
        o[c * 4 + r] = a[r] * b[c * 4] + a[4 + r] * b[c * 4 + 1] +
          a[8 + r] * b[c * 4 + 2] + a[12 + r] * b[c * 4 + 3];
      }
    }
    return o;
  }
  // T(p) * R(q) * S(s): q = [w, x, y, z] (normalised here), s = [sx, sy, sz].
  function compose(p, q, s) {
    var n = Math.hypot(q[0], q[1], q[2], q[3]) || 1;
    var w = q[0] / n, x = q[1] / n, y = q[2] / n, z = q[3] / n;
    var m = new Float32Array(16);
    m[0] = (1 - 2 * (y * y + z * z)) * s[0]; m[1] = 2 * (x * y + w * z) * s[0];
    m[2] = 2 * (x * z - w * y) * s[0];
    m[4] = 2 * (x * y - w * z) * s[1]; m[5] = (1 - 2 * (x * x + z * z)) * s[1];
    m[6] = 2 * (y * z + w * x) * s[1];
    m[8] = 2 * (x * z + w * y) * s[2]; m[9] = 2 * (y * z - w * x) * s[2];
    m[10] = (1 - 2 * (x * x + y * y)) * s[2];
    m[12] = p[0]; m[13] = p[1]; m[14] = p[2]; m[15] = 1;
    return m;
  }
  // Columns x, y, z of a rotation, translation p, scale s.
  function basis(x, y, z, p, s) {
    var m = new Float32Array(16);
    for (var i = 0; i < 3; i++) {
      m[i] = x[i] * s[0]; m[4 + i] = y[i] * s[1]; m[8 + i] = z[i] * s[2]; m[12 + i] = p[i];
    }
    m[15] = 1;
    return m;
  }
  function perspective(fovy, aspect, near, far) {
    var f = 1 / Math.tan(fovy / 2), m = new Float32Array(16);
    m[0] = f / aspect; m[5] = f; m[10] = (far + near) / (near - far); m[11] = -1;
    m[14] = 2 * far * near / (near - far);
    return m;
  }
  function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
  function add(a, b) { return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]; }
  function scale(a, k) { return [a[0] * k, a[1] * k, a[2] * k]; }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function cross(a, b) {
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  }
  function norm(a) { var n = Math.hypot(a[0], a[1], a[2]) || 1; return scale(a, 1 / n); }
  function lookAt(eye, target, up) {
    var z = norm(sub(eye, target)), x = norm(cross(up, z)), y = cross(z, x);
    var m = mat4();
    for (var i = 0; i < 3; i++) { m[i * 4] = x[i]; m[i * 4 + 1] = y[i]; m[i * 4 + 2] = z[i]; }
    m[12] = -dot(x, eye); m[13] = -dot(y, eye); m[14] = -dot(z, eye);
    return m;
  }
  // Inverse transpose of the upper 3x3 (normals under non-uniform scale).
  function normalMatrix(m) {
    var a = m[0], b = m[4], c = m[8], d = m[1], e = m[5], f = m[9], g = m[2], h = m[6], k = m[10];
    var A = e * k - f * h, B = -(d * k - f * g), C = d * h - e * g;
    var det = a * A + b * B + c * C || 1;
    // (M^-1)^T, column-major: column j holds row j of M^-1 transposed = cofactors / det.
    return new Float32Array([
      A / det, -(b * k - c * h) / det, (b * f - c * e) / det,
      B / det, (a * k - c * g) / det, -(a * f - c * d) / det,
      C / det, -(a * h - b * g) / det, (a * e - b * d) / det
    ]);
  }

  // ---- shaders ----
  function program(vs, fs) {
    function shader(type, src) {
      var s = gl.createShader(type);
      gl.shaderSource(s, src);
      gl.compileShader(s);
      if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) {
        throw new Error("shader: " + gl.getShaderInfoLog(s));
      }
      return s;
    }
    var p = gl.createProgram();
    gl.attachShader(p, shader(gl.VERTEX_SHADER, vs));
    gl.attachShader(p, shader(gl.FRAGMENT_SHADER, fs));
    gl.bindAttribLocation(p, 0, "aPos");
    gl.bindAttribLocation(p, 1, "aNormal");
    gl.linkProgram(p);
    if (!gl.getProgramParameter(p, gl.LINK_STATUS)) {
      throw new Error("shader link: " + gl.getProgramInfoLog(p));
    }
    var info = { prog: p, uni: {} };
    info.attr = { aPos: 0, aNormal: 1 };
    ["uMvp", "uNormal", "uColour"].forEach(function (n) {
      info.uni[n] = gl.getUniformLocation(p, n);
    });
    return info;
  }
  var lit = program(
    "attribute vec3 aPos; attribute vec3 aNormal; uniform mat4 uMvp; uniform mat3 uNormal;" +
    "varying vec3 vN;" +
    "void main() { vN = uNormal * aNormal; gl_Position = uMvp * vec4(aPos, 1.0); }",
    "precision mediump float; varying vec3 vN; uniform vec4 uColour;" +
    "void main() { vec3 n = normalize(vN); if (!gl_FrontFacing) n = -n;" +
    " float l = 0.38 + 0.55 * max(dot(n, normalize(vec3(0.4, -0.6, 0.8))), 0.0)" +
    " + 0.22 * max(dot(n, normalize(vec3(-0.5, 0.7, 0.3))), 0.0);" +
    " gl_FragColor = vec4(min(uColour.rgb * l, 1.0), uColour.a); }");
  var flat = program(
    "attribute vec3 aPos; uniform mat4 uMvp; void main() { gl_Position = uMvp * vec4(aPos, 1.0); }",
    "precision mediump float; uniform vec4 uColour; void main() { gl_FragColor = uColour; }");

  // ---- meshes: interleaved position + normal, 16-bit indices ----
  function mesh(vertices, indices) {
    var vb = gl.createBuffer(), ib = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, vb);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(vertices), gl.STATIC_DRAW);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, ib);
    gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, new Uint16Array(indices), gl.STATIC_DRAW);
    return { vb: vb, ib: ib, count: indices.length };
  }
  function boxMesh() {
    var v = [], idx = [];
    // For each axis a and side s: the face at coordinate s along a.
    for (var a = 0; a < 3; a++) {
      for (var s = 0; s < 2; s++) {
        var u = (a + 1) % 3, w = (a + 2) % 3, base = v.length / 6;
        var nrm = [0, 0, 0]; nrm[a] = s ? 1 : -1;
        [[0, 0], [1, 0], [1, 1], [0, 1]].forEach(function (c) {
          var p = [0, 0, 0]; p[a] = s; p[u] = c[0]; p[w] = c[1];
          v.push(p[0], p[1], p[2], nrm[0], nrm[1], nrm[2]);
        });
        // Counter-clockwise seen from outside.
        if (s) idx.push(base, base + 1, base + 2, base, base + 2, base + 3);
        else idx.push(base, base + 2, base + 1, base, base + 3, base + 2);
      }
    }
    return mesh(v, idx);
  }
  function cylinderMesh(n) {
    var v = [], idx = [], i;
    for (i = 0; i <= n; i++) {
      var t = 2 * Math.PI * i / n, c = Math.cos(t), s = Math.sin(t);
      v.push(c, s, 0, c, s, 0, c, s, 1, c, s, 0);
    }
    for (i = 0; i < n; i++) {
      var k = 2 * i;
      idx.push(k, k + 2, k + 1, k + 1, k + 2, k + 3);
    }
    [0, 1].forEach(function (z) {
      var centre = v.length / 6;
      v.push(0, 0, z, 0, 0, z ? 1 : -1);
      for (var j = 0; j <= n; j++) {
        var t = 2 * Math.PI * j / n;
        v.push(Math.cos(t), Math.sin(t), z, 0, 0, z ? 1 : -1);
      }
      for (j = 0; j < n; j++) {
        if (z) idx.push(centre, centre + 1 + j, centre + 2 + j);
        else idx.push(centre, centre + 2 + j, centre + 1 + j);
      }
    });
    return mesh(v, idx);
  }
  function sphereMesh(rings, segments) {
    var v = [], idx = [];
    for (var r = 0; r <= rings; r++) {
      var phi = Math.PI * r / rings;
      for (var s = 0; s <= segments; s++) {
        var th = 2 * Math.PI * s / segments;
        var x = Math.sin(phi) * Math.cos(th), y = Math.sin(phi) * Math.sin(th), z = Math.cos(phi);
        v.push(x, y, z, x, y, z);
      }
    }
    for (r = 0; r < rings; r++) {
      for (s = 0; s < segments; s++) {
        var a = r * (segments + 1) + s, b = a + segments + 1;
        idx.push(a, b, a + 1, a + 1, b, b + 1);
      }
    }
    return mesh(v, idx);
  }
  var BOX = boxMesh(), CYLINDER = cylinderMesh(32), SPHERE = sphereMesh(12, 20);

  // Line sets: flat list of segment end points [x, y, z, ...] drawn as gl.LINES.
  function lines(points, colour) {
    var b = gl.createBuffer();
    gl.bindBuffer(gl.ARRAY_BUFFER, b);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(points), gl.STATIC_DRAW);
    return { buf: b, count: points.length / 3, colour: colour };
  }
  function polyline(pts) {
    var out = [];
    for (var i = 1; i < pts.length; i++) out.push.apply(out, pts[i - 1].concat(pts[i]));
    return out;
  }
  var BOX_EDGES = (function () {
    var e = [];
    for (var a = 0; a < 3; a++) {
      var u = (a + 1) % 3, w = (a + 2) % 3;
      [[0, 0], [1, 0], [0, 1], [1, 1]].forEach(function (c) {
        var p = [0, 0, 0], q;
        p[u] = c[0]; p[w] = c[1]; q = p.slice(); q[a] = 1;
        e.push.apply(e, p.concat(q));
      });
    }
    return lines(e, null);
  })();

  // ---- the scene, prepared once ----
  var obstacles = scene.obstacles.map(function (o) {
    var size = sub(o.max_mm, o.min_mm);
    return {
      name: o.name, model: compose(o.min_mm, [1, 0, 0, 0], size),
      centre: scale(add(o.min_mm, o.max_mm), 0.5), top: [(o.min_mm[0] + o.max_mm[0]) / 2,
        (o.min_mm[1] + o.max_mm[1]) / 2, o.max_mm[2]]
    };
  });
  // Each shape: its mesh and its matrix within its own frame.
  var shapes = scene.shapes.map(function (s) {
    var g = s.geometry, local, m;
    if (g.type === "cylinder") {
      var d = sub(g.to_mm, g.from_mm), len = Math.hypot(d[0], d[1], d[2]) || 1e-3;
      var z = scale(d, 1 / len), helper = Math.abs(z[2]) < 0.9 ? [0, 0, 1] : [1, 0, 0];
      var x = norm(cross(helper, z)), y = cross(z, x);
      m = CYLINDER; local = basis(x, y, z, g.from_mm, [g.radius_mm, g.radius_mm, len]);
    } else if (g.type === "box") {
      m = BOX; local = compose(g.min_mm, [1, 0, 0, 0], sub(g.max_mm, g.min_mm));
    } else {
      m = SPHERE;
      local = compose(g.centre_mm, [1, 0, 0, 0], [g.radius_mm, g.radius_mm, g.radius_mm]);
    }
    return { name: s.name, kind: s.kind, mesh: m, local: local };
  });
  var keys = scene.keyframes;
  var duration = Math.max(scene.total_time_s || 0, keys.length ? keys[keys.length - 1].time_s : 0);
  // The clock ends at the estimate as the module header states it (keyframes may run a few
  // milliseconds past that rounded value).
  var shownEnd = scene.total_time_s != null ? scene.total_time_s : duration;

  // Two bounding boxes: of everything drawn (the fallback), and of the robot, the tool, its
  // trace and the points (the focus), which sets the camera, the grid and the marker size, so a
  // large floor or fence does not make the cell tiny (boxes may then reach out of the view).
  function bounds() { return { lo: [Infinity, Infinity, Infinity], hi: [-Infinity, -Infinity, -Infinity] }; }
  function extendBox(b, p) {
    for (var i = 0; i < 3; i++) { b.lo[i] = Math.min(b.lo[i], p[i]); b.hi[i] = Math.max(b.hi[i], p[i]); }
  }
  var all = bounds(), focus = bounds();
  function extend(p) { extendBox(all, p); extendBox(focus, p); }
  scene.obstacles.forEach(function (o) { extendBox(all, o.min_mm); extendBox(all, o.max_mm); });
  if (scene.base) extend(scene.base.position_mm);
  // Each shape's bounding ball in its own frame, placed by every keyframe.
  var balls = scene.shapes.map(function (s) {
    var g = s.geometry;
    if (g.type === "cylinder") {
      var d = sub(g.to_mm, g.from_mm);
      return { c: scale(add(g.from_mm, g.to_mm), 0.5), r: Math.hypot(d[0], d[1], d[2]) / 2 + g.radius_mm };
    }
    if (g.type === "box") {
      var e = sub(g.max_mm, g.min_mm);
      return { c: scale(add(g.min_mm, g.max_mm), 0.5), r: Math.hypot(e[0], e[1], e[2]) / 2 };
    }
    return { c: g.centre_mm, r: g.radius_mm };
  });
  keys.forEach(function (k) {
    extend(k.tcp_mm);
    k.poses.forEach(function (p, n) {
      var m = compose(p.position_mm, p.quat_wxyz, [1, 1, 1]), c = balls[n].c, r = balls[n].r;
      var w = [0, 1, 2].map(function (i) { return m[i] * c[0] + m[4 + i] * c[1] + m[8 + i] * c[2] + m[12 + i]; });
      extend(sub(w, [r, r, r]));
      extend(add(w, [r, r, r]));
    });
  });
  scene.waypoints.forEach(function (w) { extend(w.tcp_mm); });
  if (scene.failure) scene.failure.points.forEach(function (p) { extend(p.position_mm); });
  var framed = isFinite(focus.lo[0]) ? focus : all;
  var lo = framed.lo, hi = framed.hi;
  if (!isFinite(lo[0])) { lo = [-500, -500, 0]; hi = [500, 500, 1000]; }
  var centre = scale(add(lo, hi), 0.5);
  var radius = Math.max(300, 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]));
  var marker = radius * 0.012;

  var lineSets = [];
  (function grid() {
    var raw = radius / 8, pow = Math.pow(10, Math.floor(Math.log10(raw)));
    var step = [1, 2, 2.5, 5, 10].map(function (k) { return k * pow; })
      .filter(function (s) { return s >= raw; })[0];
    var z = Math.min(0, lo[2]), minor = [], major = [];
    var x0 = Math.floor((lo[0] - step) / step) * step, x1 = Math.ceil((hi[0] + step) / step) * step;
    var y0 = Math.floor((lo[1] - step) / step) * step, y1 = Math.ceil((hi[1] + step) / step) * step;
    for (var x = x0; x <= x1 + 1e-6; x += step) {
      (Math.round(x / step) % 5 === 0 ? major : minor).push(x, y0, z, x, y1, z);
    }
    for (var y = y0; y <= y1 + 1e-6; y += step) {
      (Math.round(y / step) % 5 === 0 ? major : minor).push(x0, y, z, x1, y, z);
    }
    lineSets.push(lines(minor, COLOURS.grid), lines(major, COLOURS.gridMajor));
    var a = step * 2;
    lineSets.push(lines([0, 0, z, a, 0, z], COLOURS.axisX),
      lines([0, 0, z, 0, a, z], COLOURS.axisY),
      lines([0, 0, z, 0, 0, z + a], COLOURS.axisZ));
    // The robot base frame: its x (front) and y axes at the base, turned by its yaw (none
    // where the base is not known: a failed choice of base).
    if (!scene.base) return;
    var b = scene.base.position_mm, yaw = scene.base.yaw_deg * Math.PI / 180;
    var bx = [Math.cos(yaw), Math.sin(yaw), 0], by = [-Math.sin(yaw), Math.cos(yaw), 0];
    lineSets.push(lines(b.concat(add(b, scale(bx, 1.5 * a))), COLOURS.axisX),
      lines(b.concat(add(b, scale(by, a))), COLOURS.axisY));
  })();
  // The TCP trace, move by move (move i from waypoint i to i + 1), each in its kind's colour;
  // without moves (a failure) or waypoints, one trace.
  if (keys.length > 1 && moves.length && moves.length === scene.waypoints.length - 1) {
    var k = 0;
    moves.forEach(function (m, i) {
      var t0 = scene.waypoints[i].time_s, t1 = scene.waypoints[i + 1].time_s, pts = [];
      // From the last keyframe at or before the move's start to its end.
      while (k + 1 < keys.length && keys[k + 1].time_s <= t0) k++;
      for (var j = k; j < keys.length && keys[j].time_s <= t1; j++) pts.push(keys[j].tcp_mm);
      if (pts.length > 1) lineSets.push(lines(polyline(pts), moveColour(m.kind)));
    });
  } else if (keys.length > 1) {
    lineSets.push(lines(polyline(keys.map(function (k) { return k.tcp_mm; })), COLOURS.trace));
  }
  var clearance = scene.clearance;
  if (clearance && clearance.points_mm) {
    lineSets.push(lines(clearance.points_mm[0].concat(clearance.points_mm[1]), COLOURS.clearance));
  }
  var failedPoints = scene.failure ? scene.failure.points : [];
  if (failedPoints.length > 1) {
    var joined = failedPoints.map(function (p) { return p.position_mm; });
    lineSets.push(lines(polyline(joined), COLOURS.failed));
  }

  // ---- text over the canvas ----
  var labelLayer = document.getElementById("labels"), labels = [];
  function label(text, anchor, cls) {
    var el = document.createElement("div");
    el.className = "label " + cls;
    el.textContent = text;
    labelLayer.appendChild(el);
    var l = { el: el, anchor: anchor };
    labels.push(l);
    return l;
  }
  function moveName(i) {
    var w = scene.waypoints;
    var ends = w[i] && w[i + 1] ? " (" + w[i].name + " \u2192 " + w[i + 1].name + ")" : "";
    var how = moves[i] && moves[i].instruction ? ": " + moves[i].instruction : "";
    return "move " + (i + 1) + ends + how;
  }
  var hitObstacle = clearance ? clearance.obstacle : null;
  obstacles.forEach(function (o) { label(o.name, o.top, "obstacle"); });
  scene.waypoints.forEach(function (w) { label(w.name, w.tcp_mm, w.kind).stack = true; });
  // Just below the point's own label (the class moves it down a line), not stacked.
  withActions.forEach(function (w) { label(w.actions.join("; "), w.tcp_mm, "action"); });
  failedPoints.forEach(function (p) {
    label(p.name + " (not joined)", p.position_mm, "failed").stack = true;
  });
  if (clearance) {
    var hit = obstacles.filter(function (o) { return o.name === hitObstacle; })[0];
    var cp = clearance.points_mm;
    var anchor = cp ? scale(add(cp[0], cp[1]), 0.5) : hit ? hit.top : centre;
    // A zoned corner's clearance (a fly-by waypoint's blend) is named by its waypoint.
    var corner = clearance.corner_waypoint != null ? scene.waypoints[clearance.corner_waypoint] : null;
    var where = corner ? "the corner at " + corner.name + " (flown by)" : moveName(clearance.move_index);
    var text = "min clearance " + clearance.distance_mm.toFixed(1) + " mm: " + clearance.shape +
      " \u2013 " + clearance.obstacle + ", " + where;
    var cl = label(text, anchor, "clearance");
    cl.el.title = "show the robot there";
    cl.el.addEventListener("click", function () {
      var w = scene.waypoints[clearance.move_index];
      setTime(clearance.time_s != null ? clearance.time_s : w ? w.time_s : 0);
      setPlaying(false);
    });
  }

  // ---- time: interpolation between keyframes ----
  function poseAt(t) {
    if (!keys.length) return null;
    var i = 0, j = keys.length - 1;
    if (t <= keys[0].time_s) j = 0;
    else if (t >= keys[j].time_s) i = j;
    else {
      while (j - i > 1) { var m = (i + j) >> 1; if (keys[m].time_s <= t) i = m; else j = m; }
    }
    var a = keys[i], b = keys[j], span = b.time_s - a.time_s;
    var u = span > 0 ? Math.min(1, Math.max(0, (t - a.time_s) / span)) : 1;
    return {
      poses: a.poses.map(function (pa, n) {
        var pb = b.poses[n], qa = pa.quat_wxyz, qb = pb.quat_wxyz;
        var sign = qa[0] * qb[0] + qa[1] * qb[1] + qa[2] * qb[2] + qa[3] * qb[3] < 0 ? -1 : 1;
        return {
          p: pa.position_mm.map(function (x, k) { return x + u * (pb.position_mm[k] - x); }),
          q: qa.map(function (x, k) { return x + u * (sign * qb[k] - x); })
        };
      }),
      tcp: a.tcp_mm.map(function (x, k) { return x + u * (b.tcp_mm[k] - x); })
    };
  }

  // ---- camera ----
  var camera = {};
  function resetCamera() {
    camera.target = centre.slice();
    camera.dist = radius / Math.sin(FOV_Y / 2) * 0.92;
    // From the robot's right, a little behind it: the robot on one side, its work beside it.
    camera.yaw = ((scene.base ? scene.base.yaw_deg : 0) - 110) * Math.PI / 180;
    camera.pitch = 26 * Math.PI / 180;
  }
  resetCamera();
  function eye() {
    var c = Math.cos(camera.pitch);
    return add(camera.target, scale([c * Math.cos(camera.yaw), c * Math.sin(camera.yaw),
      Math.sin(camera.pitch)], camera.dist));
  }

  // ---- drawing ----
  var time = 0, playing = false, dirty = true, viewProj = mat4();
  function drawMesh(m, model, colour) {
    gl.useProgram(lit.prog);
    gl.uniformMatrix4fv(lit.uni.uMvp, false, mul(viewProj, model));
    gl.uniformMatrix3fv(lit.uni.uNormal, false, normalMatrix(model));
    gl.uniform4fv(lit.uni.uColour, colour);
    gl.bindBuffer(gl.ARRAY_BUFFER, m.vb);
    gl.enableVertexAttribArray(lit.attr.aPos);
    gl.enableVertexAttribArray(lit.attr.aNormal);
    gl.vertexAttribPointer(lit.attr.aPos, 3, gl.FLOAT, false, 24, 0);
    gl.vertexAttribPointer(lit.attr.aNormal, 3, gl.FLOAT, false, 24, 12);
    gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, m.ib);
    gl.drawElements(gl.TRIANGLES, m.count, gl.UNSIGNED_SHORT, 0);
    gl.disableVertexAttribArray(lit.attr.aNormal);
  }
  function drawLines(set, model, colour) {
    if (!set.count) return;
    gl.useProgram(flat.prog);
    gl.uniformMatrix4fv(flat.uni.uMvp, false, model ? mul(viewProj, model) : viewProj);
    gl.uniform4fv(flat.uni.uColour, colour || set.colour);
    gl.bindBuffer(gl.ARRAY_BUFFER, set.buf);
    gl.enableVertexAttribArray(flat.attr.aPos);
    gl.vertexAttribPointer(flat.attr.aPos, 3, gl.FLOAT, false, 12, 0);
    gl.drawArrays(gl.LINES, 0, set.count);
  }
  function ball(p, r, colour) { drawMesh(SPHERE, compose(p, [1, 0, 0, 0], [r, r, r]), colour); }

  function resize() {
    var dpr = window.devicePixelRatio || 1;
    var w = Math.max(1, Math.round(canvas.clientWidth * dpr));
    var h = Math.max(1, Math.round(canvas.clientHeight * dpr));
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    gl.viewport(0, 0, w, h);
  }

  function draw() {
    resize();
    var e = eye(), aspect = canvas.width / canvas.height;
    viewProj = mul(perspective(FOV_Y, aspect, camera.dist / 50, camera.dist * 20),
      lookAt(e, camera.target, [0, 0, 1]));
    var bg = COLOURS.background;
    gl.clearColor(bg[0], bg[1], bg[2], bg[3]);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    gl.depthMask(true);
    gl.disable(gl.BLEND);
    gl.disable(gl.CULL_FACE);

    // Opaque: the robot and tool at the current time, markers.
    var now = poseAt(time);
    if (now) {
      now.poses.forEach(function (p, n) {
        var s = shapes[n];
        drawMesh(s.mesh, mul(compose(p.p, p.q, [1, 1, 1]), s.local),
          s.kind === "tool" ? COLOURS.tool : COLOURS.link);
      });
      ball(now.tcp, marker * 0.8, COLOURS.trace);
    }
    scene.waypoints.forEach(function (w) {
      var cell = w.kind === "cell";
      ball(w.tcp_mm, cell ? marker : marker * 0.6, cell ? COLOURS.cellPoint : COLOURS.via);
    });
    withActions.forEach(function (w) { ball(w.tcp_mm, marker * 1.3, COLOURS.action); });
    if (clearance && clearance.points_mm) {
      clearance.points_mm.forEach(function (p) { ball(p, marker * 0.7, COLOURS.clearance); });
    }
    failedPoints.forEach(function (p) { ball(p.position_mm, marker * 1.6, COLOURS.failed); });

    // Lines.
    lineSets.forEach(function (s) { drawLines(s); });
    obstacles.forEach(function (o) {
      var edge = o.name === hitObstacle ? COLOURS.hitEdge : COLOURS.obstacleEdge;
      drawLines(BOX_EDGES, o.model, edge);
    });

    // Translucent boxes, farthest first.
    gl.enable(gl.BLEND);
    gl.blendFunc(gl.SRC_ALPHA, gl.ONE_MINUS_SRC_ALPHA);
    gl.depthMask(false);
    gl.enable(gl.CULL_FACE);
    var order = obstacles.slice().sort(function (a, b) {
      var da = sub(a.centre, e), db = sub(b.centre, e);
      return dot(db, db) - dot(da, da);
    });
    [gl.FRONT, gl.BACK].forEach(function (face) {
      gl.cullFace(face);
      order.forEach(function (o) { drawMesh(BOX, o.model, COLOURS.obstacle); });
    });
    gl.depthMask(true);

    placeLabels();
    updateControls();
  }

  function placeLabels() {
    var w = canvas.clientWidth, h = canvas.clientHeight, m = viewProj;
    var placed = [];
    labels.forEach(function (l) {
      var p = l.anchor;
      var x = m[0] * p[0] + m[4] * p[1] + m[8] * p[2] + m[12];
      var y = m[1] * p[0] + m[5] * p[1] + m[9] * p[2] + m[13];
      var cw = m[3] * p[0] + m[7] * p[1] + m[11] * p[2] + m[15];
      if (cw <= 0) { l.el.style.display = "none"; return; }
      l.el.style.display = "";
      var px = (x / cw + 1) / 2 * w, py = (1 - y / cw) / 2 * h;
      if (l.width === undefined) { l.width = l.el.offsetWidth; l.height = l.el.offsetHeight; }
      // A label that would run off the right edge goes to the left of its point.
      var flip = px + l.width + 8 > w;
      // Labels of points at the same place (or close on the screen) are kept apart: a label
      // that would cover one placed before it moves down below that one.
      if (l.stack) {
        var left = flip ? px - 6 - l.width : px + 6, right = left + l.width;
        for (var moved = true, n = 0; moved && n <= placed.length; n++) {
          moved = false;
          placed.forEach(function (r) {
            var top = py - l.height / 2;
            if (left < r.right && r.left < right && top < r.bottom && r.top < top + l.height) {
              py = r.bottom + l.height / 2 + 1;
              moved = true;
            }
          });
        }
        placed.push({ left: left, right: right, top: py - l.height / 2, bottom: py + l.height / 2 });
      }
      l.el.style.left = px.toFixed(1) + "px";
      l.el.style.top = py.toFixed(1) + "px";
      l.el.classList.toggle("flip", flip);
    });
  }

  // ---- controls ----
  var playButton = document.getElementById("play"), slider = document.getElementById("time");
  var clock = document.getElementById("clock"), moveText = document.getElementById("move");
  slider.max = String(duration);
  slider.disabled = playButton.disabled = !(duration > 0);
  function setTime(t) { time = Math.min(Math.max(0, t), duration); dirty = true; }
  function setPlaying(p) {
    playing = p && duration > 0;
    playButton.innerHTML = playing ? "&#10074;&#10074;" : "&#9654;";
  }
  function updateControls() {
    slider.value = String(time);
    clock.textContent = Math.min(time, shownEnd).toFixed(2) + " / " + shownEnd.toFixed(2) + " s";
    var ws = scene.waypoints, i = ws.length - 2;
    while (i > 0 && ws[i].time_s > time) i--;
    moveText.textContent = ws.length > 1 ? moveName(Math.max(0, i)) : "";
  }
  playButton.addEventListener("click", function () {
    if (!playing && time >= duration) setTime(0);
    setPlaying(!playing);
  });
  slider.addEventListener("input", function () {
    setTime(parseFloat(slider.value));
    setPlaying(false);
  });
  window.addEventListener("keydown", function (ev) {
    if (ev.code === "Space" && ev.target === document.body) {
      ev.preventDefault();
      playButton.click();
    }
  });

  // Orbit camera: left drag rotates; right or shift drag pans; wheel zooms.
  var drag = null;
  canvas.addEventListener("contextmenu", function (ev) { ev.preventDefault(); });
  canvas.addEventListener("pointerdown", function (ev) {
    drag = { x: ev.clientX, y: ev.clientY, pan: ev.button === 2 || ev.shiftKey };
    canvas.setPointerCapture(ev.pointerId);
  });
  canvas.addEventListener("pointerup", function () { drag = null; });
  canvas.addEventListener("pointermove", function (ev) {
    if (!drag) return;
    var dx = ev.clientX - drag.x, dy = ev.clientY - drag.y;
    drag.x = ev.clientX; drag.y = ev.clientY;
    if (drag.pan) {
      var k = 2 * camera.dist * Math.tan(FOV_Y / 2) / canvas.clientHeight;
      var fwd = norm(sub(camera.target, eye())), right = norm(cross(fwd, [0, 0, 1]));
      var up = cross(right, fwd);
      camera.target = add(camera.target, add(scale(right, -dx * k), scale(up, dy * k)));
    } else {
      camera.yaw -= dx * 0.008;
      camera.pitch = Math.min(1.55, Math.max(-1.55, camera.pitch + dy * 0.008));
    }
    dirty = true;
  });
  canvas.addEventListener("wheel", function (ev) {
    ev.preventDefault();
    camera.dist *= Math.exp(Math.sign(ev.deltaY) * 0.12);
    dirty = true;
  }, { passive: false });
  canvas.addEventListener("dblclick", function () { resetCamera(); dirty = true; });
  window.addEventListener("resize", function () { dirty = true; });

  // ---- start: first frame now, then the animation loop ----
  var start = /(?:^#|&)t=([0-9.]+)/.exec(location.hash);
  setTime(start ? parseFloat(start[1]) : 0);
  setPlaying(!start && keys.length > 1);
  draw();
  var glError = gl.getError();
  if (glError !== gl.NO_ERROR) throw new Error("WebGL error " + glError + " in the first frame");
  document.body.dataset.rendered = "1";

  var last = null, hold = 0;
  function frame(stamp) {
    if (playing && last !== null) {
      var dt = Math.min(0.1, (stamp - last) / 1000);
      if (time >= duration) {
        hold += dt;
        if (hold > 1) { hold = 0; setTime(0); }
      } else {
        setTime(time + dt);
      }
      dirty = true;
    }
    last = stamp;
    if (dirty) { dirty = false; draw(); }
    requestAnimationFrame(frame);
  }
  dirty = false;
  requestAnimationFrame(frame);
})();
