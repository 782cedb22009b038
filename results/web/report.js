// The report page: sortable tables (click a header; numbers sort as numbers), the interactive Pareto
// charts (Chart.js 3, Debian libjs-chart.js) from pareto.json's rows, one colour and marker per series, and a console error for every image
// that did not load (the browser test fails on console errors).
/* global Chart, CLOTHBENCH_PARETO */
"use strict";
(function () {
  // #viewer-first (with any other hash keys, "&" between): the 3-D viewer moved up under the header, for the
  // screenshots of the viewers (report-viewer.png, the browser test); the page's own order is answers, claims,
  // tables, charts, viewer. Run as the script loads (after the sections, before the models): the viewers'
  // canvases are made in their final place.
  if (/^#(.*&)?viewer-first(&|=|$)/.test(location.hash)) {
    var viewer = document.getElementById("viewer"), header = document.querySelector("header");
    if (viewer && header) header.parentNode.insertBefore(viewer, header.nextSibling);
  }
  function key(cell) {
    var text = cell.textContent.trim(), m = text.match(/^[-+]?\d+(\.\d+)?(e[-+]?\d+)?/i);
    return m ? { n: parseFloat(m[0]), s: text } : { n: null, s: text };
  }
  function sortable(table) {
    var heads = table.querySelectorAll("thead th");
    Array.prototype.forEach.call(heads, function (th, col) {
      th.addEventListener("click", function () {
        var body = table.tBodies[0], rows = Array.prototype.slice.call(body.rows);
        var dir = th.getAttribute("data-sort") === "asc" ? -1 : 1;
        Array.prototype.forEach.call(heads, function (h) { h.removeAttribute("data-sort"); });
        th.setAttribute("data-sort", dir > 0 ? "asc" : "desc");
        rows.sort(function (a, b) {
          var x = key(a.cells[col] || a), y = key(b.cells[col] || b);
          if (x.n !== null && y.n !== null && x.n !== y.n) return dir * (x.n - y.n);
          if (x.n !== null && y.n === null) return -dir;
          if (x.n === null && y.n !== null) return dir;
          return dir * x.s.localeCompare(y.s);
        });
        rows.forEach(function (r) { body.appendChild(r); });
      });
    });
  }

  // distinct colours per series: Kelly's colours of maximum contrast (white left out; strongest first), then evenly
  // spaced hues; a marker per series as well (a chart of 16 methods must not repeat a colour)
  var palette = ["#0067a5", "#be0032", "#008856", "#f38400", "#875692", "#882d17", "#e68fac", "#848482", "#8db600",
                 "#604e97", "#f6a600", "#a1caf1", "#b3446c", "#2b3d26", "#e25822", "#c2b280", "#654522", "#dcd300",
                 "#f99379", "#222222"];
  var markers = ["circle", "triangle", "rect", "rectRot", "star", "crossRot", "cross", "rectRounded"];
  function seriesColours(n) {
    var out = palette.slice(0, Math.min(n, palette.length));
    for (var i = out.length; i < n; i++) {
      var k = i - palette.length;
      out.push("hsl(" + Math.round(360 * k / (n - palette.length)) + ", " + (k % 2 ? 55 : 80) + "%, " + (k % 2 ? 30 : 50) + "%)");
    }
    return out;
  }
  var shownColours = [];

  function paretoCharts(points) {
    var box = document.getElementById("pareto-charts");
    if (!box || typeof Chart === "undefined") return;
    var garments = [];
    points.forEach(function (p) { if (garments.indexOf(p.garment) < 0) garments.push(p.garment); });
    garments.forEach(function (g) {
      var methods = [], figure = document.createElement("figure"), canvas = document.createElement("canvas");
      figure.className = "chart";
      figure.appendChild(canvas);
      box.appendChild(figure);
      points.forEach(function (p) { if (p.garment === g && methods.indexOf(p.method) < 0) methods.push(p.method); });
      var colours = seriesColours(methods.length);
      shownColours.push(colours);
      var datasets = methods.map(function (m, i) {
        var c = colours[i];
        var mine = points.filter(function (p) { return p.garment === g && p.method === m; });
        return {
          label: m, borderColor: c, pointStyle: markers[i % markers.length], pointRadius: 4, borderWidth: 1.5,
          backgroundColor: mine.map(function (p) { return p.meets ? c : "rgba(255,255,255,0)"; }),
          data: mine.map(function (p) { return { x: p.ms, y: p.crossings, p: p }; })
        };
      });
      new Chart(canvas, {
        type: "scatter", data: { datasets: datasets },
        options: {
          animation: false, maintainAspectRatio: false,
          plugins: {
            legend: { position: "right", labels: { boxWidth: 10, font: { size: 10 } } },
            title: { display: true, text: "pareto: " + g },
            tooltip: { callbacks: { label: function (ctx) {
              var p = ctx.raw.p;
              return p.name + ": " + p.ms.toPrecision(3) + " ms/iteration, crossings " + p.crossings.toFixed(2) +
                " %, inside " + p.inside.toFixed(2) + " %, " + p.vertices + " vertices" + (p.meets ? ", meets the limits" : "");
            } } }
          },
          scales: {
            x: { type: "logarithmic", title: { display: true, text: "time per iteration [ms]" } },
            y: { title: { display: true, text: "structural springs crossing the body [%]" } }
          }
        }
      });
    });
  }

  window.addEventListener("load", function () {
    Array.prototype.forEach.call(document.querySelectorAll("table.sortable"), sortable);
    Array.prototype.forEach.call(document.querySelectorAll("img"), function (img) {
      if (!img.complete || img.naturalWidth === 0) console.error("report: image " + img.getAttribute("src") + " missing");
    });
    if (typeof CLOTHBENCH_PARETO !== "undefined") paretoCharts(CLOTHBENCH_PARETO);
    // for the browser test: each chart's series colours, and what is wider than the window (the page itself, and
    // tables that scroll inside their box)
    var root = document.documentElement;
    root.setAttribute("data-chart-colours", JSON.stringify(shownColours));
    var wide = [];
    Array.prototype.forEach.call(document.querySelectorAll(".table"), function (box) {
      if (box.scrollWidth > box.clientWidth + 1) {
        var section = box.closest("section");
        wide.push((section ? section.id : "?") + ": " + box.scrollWidth + " px in " + box.clientWidth);
      }
    });
    root.setAttribute("data-page-overflow", String(Math.max(0, root.scrollWidth - root.clientWidth)));
    root.setAttribute("data-wide-tables", JSON.stringify(wide));
  });
})();
