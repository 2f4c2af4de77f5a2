(function () {
  "use strict";
  // voussoir 3D report viewer: WebGL 1, no library. Flat-shaded Lambert triangles for the
  // bodies, unlit lines for edges, thin lit prisms for cracks and force arrows (WebGL lines are
  // one pixel wide on most platforms). Orbit camera about the model's centre, z up.
  var D = JSON.parse(document.getElementById("voussoir-data").textContent);
  var canvas = document.getElementById("v3-canvas");
  var gl = canvas.getContext("webgl", { antialias: true, preserveDrawingBuffer: true });
  if (!gl) {
    canvas.hidden = true;
    document.getElementById("v3-nogl").hidden = false;
    document.body.setAttribute("data-ready", "nogl");
    return;
  }

  // ---- small vector and matrix helpers (matrices column-major, as WebGL wants) ----
  function sub(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }
  function add(a, b) { return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]; }
  function scl(a, s) { return [a[0] * s, a[1] * s, a[2] * s]; }
  function dot(a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  function cross(a, b) { return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]; }
  function len(a) { return Math.sqrt(dot(a, a)); }
  function unit(a) { var l = len(a); return l > 0 ? scl(a, 1 / l) : [0, 0, 1]; }
  function mul(a, b) {
    var o = new Array(16);
    for (var c = 0; c < 4; c++) {
      for (var r = 0; r < 4; r++) {
        var s = 0;
        for (var k = 0; k < 4; k++) { s += a[k * 4 + r] * b[c * 4 + k]; }
        o[c * 4 + r] = s;
      }
    }
    return o;
  }
  function lookAt(eye, target, up) {
    var f = unit(sub(target, eye)), s = unit(cross(f, up)), u = cross(s, f);
    return [s[0], u[0], -f[0], 0, s[1], u[1], -f[1], 0, s[2], u[2], -f[2], 0,
      -dot(s, eye), -dot(u, eye), dot(f, eye), 1];
  }
  function perspective(fovy, aspect, near, far) {
    var f = 1 / Math.tan(fovy / 2), nf = 1 / (near - far);
    return [f / aspect, 0, 0, 0, 0, f, 0, 0, 0, 0, (far + near) * nf, -1, 0, 0, 2 * far * near * nf, 0];
  }

  // ---- finite rigid motion of a body at displacement scale s: x -> c + s u + R(s θ)(x - c) ----
  function mover(body, s) {
    var c = body.c, m = body.m, t = [s * m[0], s * m[1], s * m[2]];
    var th = [s * m[3], s * m[4], s * m[5]], a = len(th);
    var k = a > 0 ? scl(th, 1 / a) : [0, 0, 1], ca = Math.cos(a), sa = Math.sin(a);
    function rot(v) {
      if (a === 0) { return v; }
      return add(add(scl(v, ca), scl(cross(k, v), sa)), scl(k, dot(k, v) * (1 - ca)));
    }
    return { point: function (x) { return add(add(c, t), rot(sub(x, c))); }, vector: rot };
  }
  function bodyOf(ref) {
    if (!ref) { return null; }
    return ref[0] === "b" ? D.blocks[ref[1]] : D.supports[ref[1]];
  }

  // ---- model size ----
  var lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  D.blocks.concat(D.supports).forEach(function (b) {
    b.v.forEach(function (p) {
      for (var i = 0; i < 3; i++) { lo[i] = Math.min(lo[i], p[i]); hi[i] = Math.max(hi[i], p[i]); }
    });
  });
  if (!isFinite(lo[0])) { lo = [-1, -1, -1]; hi = [1, 1, 1]; }
  var centre = scl(add(lo, hi), 0.5), radius = Math.max(len(sub(hi, lo)) / 2, 1e-9);

  // ---- shader ----
  var VS = "attribute vec3 p; attribute vec3 n; attribute vec3 col; uniform mat4 M;" +
    "varying vec3 vn; varying vec3 vc; void main(){ gl_Position = M * vec4(p, 1.0); vn = n; vc = col; }";
  var FS = "precision mediump float; varying vec3 vn; varying vec3 vc; uniform float lit;" +
    "void main(){ vec3 L1 = normalize(vec3(0.45, -0.65, 0.75)); vec3 L2 = normalize(vec3(-0.6, 0.3, 0.2));" +
    " float d = abs(dot(normalize(vn + vec3(1e-6)), L1)); float d2 = abs(dot(normalize(vn + vec3(1e-6)), L2));" +
    " vec3 c = lit > 0.5 ? vc * (0.38 + 0.55 * d + 0.17 * d2) : vc; gl_FragColor = vec4(min(c, vec3(1.0)), 1.0); }";
  function shader(type, src) {
    var s = gl.createShader(type);
    gl.shaderSource(s, src);
    gl.compileShader(s);
    if (!gl.getShaderParameter(s, gl.COMPILE_STATUS)) { throw new Error(gl.getShaderInfoLog(s)); }
    return s;
  }
  var prog = gl.createProgram();
  gl.attachShader(prog, shader(gl.VERTEX_SHADER, VS));
  gl.attachShader(prog, shader(gl.FRAGMENT_SHADER, FS));
  gl.linkProgram(prog);
  if (!gl.getProgramParameter(prog, gl.LINK_STATUS)) { throw new Error(gl.getProgramInfoLog(prog)); }
  gl.useProgram(prog);
  var aP = gl.getAttribLocation(prog, "p"), aN = gl.getAttribLocation(prog, "n"), aC = gl.getAttribLocation(prog, "col");
  var uM = gl.getUniformLocation(prog, "M"), uLit = gl.getUniformLocation(prog, "lit");
  var triBuf = gl.createBuffer(), lineBuf = gl.createBuffer(), triCount = 0, lineCount = 0;

  // ---- colours ----
  var BLOCK = [0.86, 0.79, 0.64], SUPPORT = [0.62, 0.62, 0.60], FIXED = [0.50, 0.50, 0.56];
  var EDGE = [0.25, 0.22, 0.18], GHOST = [0.70, 0.70, 0.70], CRACK = [0.85, 0.10, 0.10];
  var FORCE = [0.12, 0.35, 0.80];

  // ---- geometry at the current scale and toggles ----
  var ui = {
    scale: document.getElementById("v3-scale"), out: document.getElementById("v3-scale-out"),
    cracks: document.getElementById("v3-cracks"), forces: document.getElementById("v3-forces"),
    supports: document.getElementById("v3-supports"), ghost: document.getElementById("v3-ghost"),
    reset: document.getElementById("v3-reset")
  };
  var base = D.scale > 0 ? D.scale : 0;
  if (base > 0) {
    ui.scale.max = String(3 * base); ui.scale.step = String(base / 100); ui.scale.value = String(base);
  } else {
    ui.scale.disabled = true; ui.scale.value = "0";
  }
  function fmt(s) { return s >= 100 ? String(Math.round(s)) : String(Number(s.toPrecision(3))); }

  function build() {
    var s = Number(ui.scale.value) || 0, T = [], L = [];
    ui.out.textContent = fmt(s);
    function tri(a, b, c, n, col) { [a, b, c].forEach(function (q) { T.push(q[0], q[1], q[2], n[0], n[1], n[2], col[0], col[1], col[2]); }); }
    function line(a, b, col) { [a, b].forEach(function (q) { L.push(q[0], q[1], q[2], 0, 0, 0, col[0], col[1], col[2]); }); }
    function solid(body, col, moved) {
      var mv = mover(body, moved ? s : 0), P = body.v.map(mv.point);
      body.t.forEach(function (t) {
        var n = unit(cross(sub(P[t[1]], P[t[0]]), sub(P[t[2]], P[t[0]])));
        tri(P[t[0]], P[t[1]], P[t[2]], n, col);
      });
      body.f.forEach(function (f) {
        for (var k = 0; k < f.length; k++) { line(P[f[k]], P[f[(k + 1) % f.length]], EDGE); }
      });
    }
    // A thin square prism from a to b (width w), for cracks and arrows.
    function prism(a, b, w, col) {
      var d = sub(b, a); if (len(d) === 0) { return; }
      var e = unit(d), h = Math.abs(e[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
      var u = scl(unit(cross(e, h)), w / 2), v = scl(unit(cross(e, u)), w / 2);
      var ring = [add(u, v), sub(u, v), scl(add(u, v), -1), sub(v, u)];
      for (var k = 0; k < 4; k++) {
        var r0 = ring[k], r1 = ring[(k + 1) % 4], n = unit(add(r0, r1));
        tri(add(a, r0), add(a, r1), add(b, r1), n, col);
        tri(add(a, r0), add(b, r1), add(b, r0), n, col);
      }
    }
    function cone(a, b, w, col) {
      var d = sub(b, a); if (len(d) === 0) { return; }
      var e = unit(d), h = Math.abs(e[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
      var u = scl(unit(cross(e, h)), w), v = scl(unit(cross(e, u)), w);
      var ring = [u, v, scl(u, -1), scl(v, -1)];
      for (var k = 0; k < 4; k++) {
        var p0 = add(a, ring[k]), p1 = add(a, ring[(k + 1) % 4]);
        tri(p0, p1, b, unit(cross(sub(p1, p0), sub(b, p0))), col);
      }
    }
    D.blocks.forEach(function (b) { solid(b, BLOCK, true); });
    if (ui.supports.checked) {
      D.supports.forEach(function (b) { solid(b, b.fixed ? FIXED : SUPPORT, true); });
    }
    if (ui.ghost.checked && s > 0) {
      D.blocks.forEach(function (b) {
        b.f.forEach(function (f) {
          for (var k = 0; k < f.length; k++) { line(b.v[f[k]], b.v[f[(k + 1) % f.length]], GHOST); }
        });
      });
    }
    var w = radius * 0.009;
    if (ui.cracks.checked) {
      D.joints.forEach(function (j) {
        if (j.state === "closed") { return; }
        [j.a, j.b].forEach(function (ref) {
          var body = bodyOf(ref); if (!body) { return; }
          var mv = mover(body, s), P = j.p.map(mv.point);
          for (var k = 0; k < P.length; k++) { prism(P[k], P[(k + 1) % P.length], w, CRACK); }
        });
      });
    }
    if (ui.forces.checked) {
      var Nmax = 0;
      D.joints.forEach(function (j) { if (j.cp && j.N > Nmax) { Nmax = j.N; } });
      D.joints.forEach(function (j) {
        if (!j.cp || !(j.N > 0) || Nmax <= 0) { return; }
        var body = bodyOf(j.b) || bodyOf(j.a); if (!body) { return; }
        var mv = mover(body, s), at = mv.point(j.cp), n = unit(mv.vector(j.n));
        var l = 0.3 * radius * j.N / Nmax, tail = sub(at, scl(n, l)), neck = sub(at, scl(n, Math.min(l * 0.35, 6 * w)));
        prism(tail, neck, w * 0.9, FORCE);
        cone(neck, at, w * 1.8, FORCE);
        // The centre of pressure: a small diamond.
        var r = 1.6 * w;
        [[r, 0, 0], [-r, 0, 0], [0, r, 0], [0, -r, 0]].forEach(function (e) {
          cone(add(at, e), at, r * 0.8, FORCE);
        });
      });
    }
    gl.bindBuffer(gl.ARRAY_BUFFER, triBuf);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(T), gl.DYNAMIC_DRAW);
    triCount = T.length / 9;
    gl.bindBuffer(gl.ARRAY_BUFFER, lineBuf);
    gl.bufferData(gl.ARRAY_BUFFER, new Float32Array(L), gl.DYNAMIC_DRAW);
    lineCount = L.length / 9;
  }

  // ---- camera ----
  var cam = {};
  function resetCamera() {
    cam.yaw = -1.0; cam.pitch = 0.42; cam.target = centre.slice(); cam.dist = radius / Math.sin(0.5 * 0.61) * 0.9;
  }
  resetCamera();
  function eye() {
    var cp = Math.cos(cam.pitch);
    return add(cam.target, scl([cp * Math.cos(cam.yaw), cp * Math.sin(cam.yaw), Math.sin(cam.pitch)], cam.dist));
  }
  function draw() {
    var W = canvas.width, H = canvas.height;
    gl.viewport(0, 0, W, H);
    gl.clearColor(0.984, 0.980, 0.969, 1);
    gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    gl.enable(gl.DEPTH_TEST);
    var P = perspective(0.61, W / H, cam.dist / 100, cam.dist * 100);
    gl.uniformMatrix4fv(uM, false, new Float32Array(mul(P, lookAt(eye(), cam.target, [0, 0, 1]))));
    function attribs(buf) {
      gl.bindBuffer(gl.ARRAY_BUFFER, buf);
      gl.enableVertexAttribArray(aP); gl.vertexAttribPointer(aP, 3, gl.FLOAT, false, 36, 0);
      gl.enableVertexAttribArray(aN); gl.vertexAttribPointer(aN, 3, gl.FLOAT, false, 36, 12);
      gl.enableVertexAttribArray(aC); gl.vertexAttribPointer(aC, 3, gl.FLOAT, false, 36, 24);
    }
    // Faces pushed back a little so that their edges are drawn on top.
    gl.enable(gl.POLYGON_OFFSET_FILL);
    gl.polygonOffset(1, 1);
    attribs(triBuf); gl.uniform1f(uLit, 1); gl.drawArrays(gl.TRIANGLES, 0, triCount);
    gl.disable(gl.POLYGON_OFFSET_FILL);
    attribs(lineBuf); gl.uniform1f(uLit, 0); gl.drawArrays(gl.LINES, 0, lineCount);
  }
  var pending = false;
  function redraw() {
    if (pending) { return; }
    pending = true;
    window.requestAnimationFrame(function () { pending = false; draw(); });
  }
  function rotate(dx, dy) {
    cam.yaw -= dx * 0.008;
    cam.pitch = Math.max(-1.55, Math.min(1.55, cam.pitch + dy * 0.008));
  }
  function pan(dx, dy) {
    var e = eye(), f = unit(sub(cam.target, e)), r = unit(cross(f, [0, 0, 1])), u = cross(r, f);
    var k = cam.dist * 2 * Math.tan(0.305) / canvas.clientHeight;
    cam.target = add(cam.target, add(scl(r, -dx * k), scl(u, dy * k)));
  }

  // ---- input ----
  var drag = null;
  canvas.addEventListener("contextmenu", function (e) { e.preventDefault(); });
  canvas.addEventListener("pointerdown", function (e) {
    drag = { x: e.clientX, y: e.clientY, pan: e.button === 2 || e.shiftKey };
    canvas.setPointerCapture(e.pointerId);
    canvas.style.cursor = "grabbing";
  });
  canvas.addEventListener("pointermove", function (e) {
    if (!drag) { return; }
    var dx = e.clientX - drag.x, dy = e.clientY - drag.y;
    drag.x = e.clientX; drag.y = e.clientY;
    if (drag.pan) { pan(dx, dy); } else { rotate(dx, dy); }
    redraw();
  });
  function end() { drag = null; canvas.style.cursor = "grab"; }
  canvas.addEventListener("pointerup", end);
  canvas.addEventListener("pointercancel", end);
  canvas.addEventListener("wheel", function (e) {
    e.preventDefault();
    cam.dist *= Math.exp(Math.max(-0.5, Math.min(0.5, e.deltaY * 0.0015)));
    redraw();
  }, { passive: false });
  [ui.scale, ui.cracks, ui.forces, ui.supports, ui.ghost].forEach(function (el) {
    el.addEventListener("input", function () { build(); redraw(); });
    el.addEventListener("change", function () { build(); redraw(); });
  });
  ui.reset.addEventListener("click", function () {
    resetCamera();
    if (base > 0) { ui.scale.value = String(base); }
    build(); redraw();
  });
  function fit() {
    var w = Math.max(300, Math.round(canvas.clientWidth * (window.devicePixelRatio || 1)));
    var h = Math.round(w * 0.62);
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
  }
  window.addEventListener("resize", function () { fit(); draw(); });

  // Test hooks: rotate as a drag of (dx, dy) pixels would, and redraw now.
  window.__voussoirRotate = function (dx, dy) { rotate(dx, dy); draw(); return [cam.yaw, cam.pitch]; };
  window.__voussoirCounts = function () { return { triangles: triCount / 3, lines: lineCount / 2 }; };

  fit();
  build();
  draw();
  document.body.setAttribute("data-ready", "1");
})();
