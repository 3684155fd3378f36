"""The script of a compact path page (:mod:`kresling.view.path_page`): it unpacks plotly's
JavaScript and the frames, draws the first frame, and then draws frame after frame from
the node positions: the panels' mesh, the crease polylines and the curve's marker, with
one ``Plotly.restyle`` per frame.

Page elements it reads: ``#kresling-plotly`` (plotly.min.js, deflated and encoded),
``#kresling-figure`` (the figure of the first frame without coordinates, and what the
frames are: their names, rows, the box, the polylines' node orders) and
``#kresling-frames`` (the positions, see :func:`kresling.view.path_page.encode_frames`).
It sets ``window.kreslingShowIncrement(K)`` (the frame nearest increment K) and
``window.kreslingReady`` (a promise, resolved once the first frame is drawn), reads
``#frame=K`` from the address and follows its changes, and plays and pauses with the
buttons: one frame every 60 ms, or, for a motion in time (``frames.times`` [s] and
``frames.scale``, wall seconds per second of the motion), each frame at its own time.
A browser without ``DecompressionStream`` gets a line saying what it needs.
"""

__all__ = ["PAGE_SCRIPT"]

PAGE_SCRIPT = r"""
(function () {
  var gd = document.getElementById('kresling-view');
  function text(id) { return document.getElementById(id).textContent.trim(); }
  if (typeof DecompressionStream === 'undefined') {
    gd.textContent = 'This page needs a browser that can decompress (DecompressionStream: ' +
      'Chromium 80, Firefox 113, Safari 16.4 or later).';
    return;
  }
  var spec = JSON.parse(text('kresling-figure'));
  var info = spec.frames, F = info.rows.length, M = 3 * info.nodes;
  var q = null, shown = -1, playing = false;

  function unpack(raw) {
    var count = F * M, f, m;
    q = new Uint16Array(count);
    for (var i = 0; i < count; i++) { q[i] = raw[i] | (raw[count + i] << 8); }
    for (var pass = 0; pass < 2; pass++) {        // the two differences summed back
      for (f = 1; f < F; f++) {
        for (m = 0; m < M; m++) { q[f * M + m] += q[(f - 1) * M + m]; }
      }
    }
  }
  function points(i) {
    var p = new Float64Array(M), base = i * M;
    for (var m = 0; m < M; m++) {
      var k = m % 3;
      p[m] = info.low[k] + q[base + m] / 65535 * info.span[k];
    }
    return p;
  }
  function along(p, order, k) {
    var out = new Array(order.length);
    for (var n = 0; n < order.length; n++) {
      out[n] = order[n] < 0 ? null : p[3 * order[n] + k];
    }
    return out;
  }
  function coordinates(i) {             // x, y, z of every moving 3D trace, in order
    var p = points(i), x = [], y = [], z = [];
    if (info.mesh) {
      var all = new Array(info.nodes);
      for (var n = 0; n < info.nodes; n++) { all[n] = n; }
      x.push(along(p, all, 0)); y.push(along(p, all, 1)); z.push(along(p, all, 2));
    }
    info.orders.forEach(function (order) {
      x.push(along(p, order, 0)); y.push(along(p, order, 1)); z.push(along(p, order, 2));
    });
    return {x: x, y: y, z: z};
  }
  var moving = [];
  for (var t = 0; t < (info.mesh ? 1 : 0) + info.orders.length; t++) { moving.push(t); }
  var markerIndex = spec.data.length - 1, curveIndex = spec.data.length - 2;

  function draw(i) {
    shown = i;
    var c = coordinates(i);
    var done = Plotly.restyle(gd, c, moving);
    if (info.curve) {
      var curve = gd.data[curveIndex], row = info.rows[i];
      done = done.then(function () {
        return Plotly.restyle(gd, {x: [[curve.x[row]]], y: [[curve.y[row]]]}, [markerIndex]);
      });
    }
    return done;
  }
  function show(i) {                    // draw frame i and move the slider there
    return draw(i).then(function () {
      return Plotly.relayout(gd, {'sliders[0].active': i});
    });
  }
  function nearest(k) {
    var best = 0;
    for (var i = 1; i < F; i++) {
      if (Math.abs(parseInt(info.names[i], 10) - k) <
          Math.abs(parseInt(info.names[best], 10) - k)) { best = i; }
    }
    return best;
  }
  function fromHash() {
    var m = /(?:^#|&)frame=(\d+)/.exec(window.location.hash);
    return m ? parseInt(m[1], 10) : null;
  }
  var clock = null;                     // a motion in time: when and where play started
  function play() {
    if (!playing) { return; }
    if (shown >= F - 1) { playing = false; return; }
    if (!info.times) {
      show(shown + 1).then(function () { setTimeout(play, info.duration); });
      return;
    }
    // Each frame at its own time, scaled: frame i is due at the start's wall time plus
    // (t_i - t_start) * scale (late frames are drawn at once, so the clock is kept).
    var next = shown + 1;
    var due = clock.wall + (info.times[next] - info.times[clock.frame]) * info.scale * 1000;
    setTimeout(function () {
      if (playing) { show(next).then(play); }
    }, Math.max(0, due - performance.now()));
  }
  function start() {
    var first = fromHash() === null ? 0 : nearest(fromHash());
    var c = coordinates(first), k = 0;
    moving.forEach(function (index) {
      spec.data[index].x = c.x[k]; spec.data[index].y = c.y[k]; spec.data[index].z = c.z[k];
      k++;
    });
    if (info.curve) {
      var row = info.rows[first], curve = spec.data[curveIndex];
      spec.data[markerIndex].x = [curve.x[row]];
      spec.data[markerIndex].y = [curve.y[row]];
    }
    spec.layout.sliders[0].active = first;
    shown = first;
    return Plotly.newPlot(gd, spec.data, spec.layout, spec.config).then(function () {
      gd.on('plotly_sliderchange', function (event) {
        if (event.slider.active !== shown) { draw(event.slider.active); }
      });
      gd.on('plotly_buttonclicked', function (event) {
        var what = event.button.args && event.button.args[0];
        if (what === 'play') {
          if (!playing) {
            playing = true;
            if (shown >= F - 1) { shown = -1; }
            clock = {wall: performance.now(), frame: Math.max(shown, 0)};
            if (info.times && shown < 0) { show(0).then(play); } else { play(); }
          }
        } else if (what === 'pause') { playing = false; }
      });
      window.addEventListener('hashchange', function () {
        var k = fromHash();
        if (k !== null) { show(nearest(k)); }
      });
      window.kreslingShowIncrement = function (k) { return show(nearest(k)); };
    });
  }
  window.kreslingReady = kreslingInflate(kreslingDecode85(text('kresling-plotly')))
    .then(function (js) {
      var script = document.createElement('script');
      script.textContent = new TextDecoder().decode(js);
      document.head.appendChild(script);
      return kreslingInflate(kreslingDecode85(text('kresling-frames')));
    })
    .then(function (raw) { unpack(raw); return start(); })
    .catch(function (error) {
      gd.textContent = 'The view could not be drawn: ' + error;
      console.error(error);
    });
})();
"""
