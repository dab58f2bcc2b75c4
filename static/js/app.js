/*
 * The page's one script. Draws every chart from its <script type="application/json">
 * figure (on load and after each htmx swap), loading Plotly only when the first chart
 * arrives so the empty form stays light, keeps aria-invalid in step with the inline
 * error messages that htmx swaps out of band, copies share links, lets a click on a result
 * row open its detail (whose body htmx loads on first opening), marks a detail busy while
 * it loads, keeps the last results (dimmed) while a field is being retyped, and sizes
 * the charts and dates the printed report. Nothing here is needed for the form to work.
 */
(function () {
  "use strict";

  var PLOT_CONFIG = {
    responsive: true,
    displaylogo: false,
    modeBarButtonsToRemove: ["select2d", "lasso2d", "sendChartToCloud"],
  };
  var plotlyLoading = false;

  // Plotly is large: fetch it (a 'self' script, as the CSP allows) once charts need it
  function loadPlotly() {
    var results = document.getElementById("results");
    if (plotlyLoading || !results || !results.dataset.plotly) {
      return;
    }
    plotlyLoading = true;
    var script = document.createElement("script");
    script.src = results.dataset.plotly;
    script.addEventListener("load", function () {
      drawCharts(document);
    });
    document.head.appendChild(script);
  }

  function drawCharts(root) {
    var figures = root.querySelectorAll('script[type="application/json"][data-chart]');
    if (!figures.length) {
      return;
    }
    if (!window.Plotly) {
      loadPlotly();
      return;
    }
    figures.forEach(function (script) {
      var target = document.getElementById(script.dataset.chart);
      if (!target || target.classList.contains("js-plotly-plot")) {
        return;
      }
      var figure = JSON.parse(script.textContent);
      var config = Object.assign({}, PLOT_CONFIG, {
        toImageButtonOptions: { format: "png", filename: script.dataset.chart, scale: 2 },
      });
      window.Plotly.newPlot(target, figure.data, figure.layout, config);
    });
  }

  function syncInvalid() {
    var form = document.querySelector("form[hx-get]");
    if (!form) {
      return;
    }
    form.querySelectorAll("input[name], select[name]").forEach(function (field) {
      var message = document.getElementById("e-" + field.name);
      if (!message) {
        return;
      }
      if (message.textContent.trim()) {
        field.setAttribute("aria-invalid", "true");
      } else {
        field.removeAttribute("aria-invalid");
      }
    });
  }

  function revealCopyButtons() {
    document.querySelectorAll("button.copy-link[hidden], button.print-report[hidden]").forEach(function (button) {
      button.hidden = false;
    });
  }

  function copyWithSelection(text) {
    var area = document.createElement("textarea");
    area.value = text;
    area.setAttribute("readonly", "");
    area.className = "offscreen";
    document.body.appendChild(area);
    area.select();
    var copied = false;
    try {
      copied = document.execCommand("copy");
    } finally {
      area.remove();
    }
    return copied ? Promise.resolve() : Promise.reject(new Error("copy refused"));
  }

  function copyText(text) {
    if (navigator.clipboard && window.isSecureContext) {
      return navigator.clipboard.writeText(text).catch(function () {
        return copyWithSelection(text);
      });
    }
    return copyWithSelection(text);
  }

  function onCopy(button) {
    var url = new URL(button.dataset.url, window.location.href).href;
    var status = button.parentElement.querySelector(".copy-status");
    copyText(url).then(
      function () {
        status.textContent = "Link copied.";
      },
      function () {
        status.textContent = "Copy this link: " + url;
      }
    );
  }

  function onClick(event) {
    if (event.target.closest("button.print-report")) {
      window.print();
      return;
    }
    var button = event.target.closest("button.copy-link");
    if (button) {
      onCopy(button);
      return;
    }
    var row = event.target.closest("tr.main[data-detail]");
    if (row && !event.target.closest("a, button, summary, input, select, label")) {
      var detail = document.getElementById(row.dataset.detail);
      if (detail) {
        detail.open = !detail.open;
      }
    }
  }

  // a result's <details class="detail"> loads its body from /detail when first opened
  function markLoading(event) {
    var detail = event.detail.elt;
    if (detail.matches("details.detail")) {
      if (event.type === "htmx:beforeRequest") {
        detail.setAttribute("aria-busy", "true");
      } else {
        detail.removeAttribute("aria-busy");
      }
    }
  }

  var PRINT_FONT_SIZE = 8;
  // printed, the plot takes the top margin the screen keeps clear for the toolbar
  var PRINT_TOP_MARGIN = 18;
  var SCREEN_LAYOUT = {
    width: null,
    height: null,
    autosize: true,
    "font.size": 12,
    "margin.t": 36,
  };

  function eachChart(action) {
    if (!window.Plotly) {
      return;
    }
    document.querySelectorAll(".chart.js-plotly-plot").forEach(action);
  }

  function dateReport() {
    var today = new Date().toISOString().slice(0, 10);
    document.querySelectorAll("time.print-date").forEach(function (time) {
      time.textContent = today;
      time.setAttribute("datetime", today);
    });
    document.querySelectorAll("a.print-link").forEach(function (link) {
      link.textContent = link.href;
    });
  }

  // a field being retyped answers with errors only: keep the last results, dimmed
  function keepStaleResults(event) {
    var target = event.detail.target;
    if (!target || target.id !== "results") {
      return;
    }
    var keep = event.detail.serverResponse.indexOf("data-keep-results") !== -1;
    var note = target.querySelector(".stale-note");
    if (keep && note) {
      event.detail.swapOverride = "none";
      target.classList.add("stale");
      note.hidden = false;
    } else {
      target.classList.remove("stale");
      purgeCharts(target);
    }
  }

  // the swap replaces the charts: Plotly.purge drops each old chart's window resize
  // listener (kept for ever otherwise) and its thousands of SVG nodes, which htmx would
  // walk one by one while cleaning up the old results
  function purgeCharts(target) {
    eachChart(function (chart) {
      if (target.contains(chart)) {
        window.Plotly.purge(chart);
      }
    });
  }

  // called once the print stylesheet applies, so each chart is drawn at its printed box's
  // size (a fixed print width overflowed the narrower printed boxes and was clipped)
  function sizeForPrint() {
    eachChart(function (chart) {
      window.Plotly.relayout(chart, {
        width: chart.clientWidth,
        height: chart.clientHeight,
        "font.size": PRINT_FONT_SIZE,
        "margin.t": PRINT_TOP_MARGIN,
      });
    });
  }

  function onPrintMedia(event) {
    if (event.matches) {
      sizeForPrint();
    } else {
      sizeForScreen();
    }
  }

  function sizeForScreen() {
    eachChart(function (chart) {
      window.Plotly.relayout(chart, SCREEN_LAYOUT);
    });
  }

  function refresh() {
    drawCharts(document);
    syncInvalid();
    revealCopyButtons();
  }

  document.addEventListener("DOMContentLoaded", refresh);
  document.addEventListener("htmx:afterSettle", refresh);
  document.addEventListener("click", onClick);
  document.addEventListener("htmx:beforeSwap", keepStaleResults);
  document.addEventListener("htmx:beforeRequest", markLoading);
  document.addEventListener("htmx:afterRequest", markLoading);
  window.addEventListener("beforeprint", dateReport);
  window.matchMedia("print").addEventListener("change", onPrintMedia);
})();
