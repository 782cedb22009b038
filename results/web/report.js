// The report page: sortable tables (click a header; numbers sort as numbers), the interactive Pareto
// charts (Chart.js 3, Debian libjs-chart.js) from pareto.json's rows, and a console error for every image
// that did not load (the browser test fails on console errors).
/* global Chart, CLOTHBENCH_PARETO */
"use strict";
(function () {
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

  var palette = ["#c83c3c", "#3c6ec8", "#dca028", "#46a05a", "#9650b4", "#28aaaa", "#777777", "#e377c2", "#8c564b"];
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
      var datasets = methods.map(function (m, i) {
        var c = palette[i % palette.length];
        var mine = points.filter(function (p) { return p.garment === g && p.method === m; });
        return {
          label: m, borderColor: c,
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
  });
})();
