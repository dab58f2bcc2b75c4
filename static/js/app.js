/*
 * The page's one script. Fetches a result's charts (/charts) as soon as its answer arrives
 * and draws each from its <script type="application/json"> figure once the table is
 * painted: those in view at once (giving way to a keystroke), the others when scrolled
 * to or once no field has been edited for a moment. Loads Plotly only when the first
 * chart arrives so the empty form stays light, shows each field's error once the field
 * has been left or the form submitted and keeps aria-invalid in step with it, copies
 * share links, lets a click on a result row open its detail, loads a detail's body (and
 * the rejected list) on first opening and marks it busy meanwhile, writes each cell's
 * phone label from its column's heading, keeps the last results (dimmed) while a field
 * is being retyped, and sizes the charts and dates the printed report. Nothing here is needed for the form to work.
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
    var holder = document.querySelector("[data-plotly]");
    if (plotlyLoading || !holder) {
      return;
    }
    plotlyLoading = true;
    var script = document.createElement("script");
    script.src = holder.dataset.plotly;
    script.addEventListener("load", function () {
      drawCharts(document);
    });
    document.head.appendChild(script);
  }

  // charts wait for the table to be painted, then draw (a keystroke waiting is not held
  // up behind all of them: see inputWaiting). Those in view draw at once, and
  // "charts:drawn" says how many (an answer is finished when they are); the others draw
  // as they are scrolled into view, or QUIET_MS after those in view are drawn unless a
  // field is edited meanwhile (then they wait to be seen, or for the next answer's charts)
  var QUIET_MS = 500;
  var chartQueue = [];
  var waiting = [];
  var drawing = false;
  var drawnInView = 0;
  var quietTimer = null;
  var watcher = window.IntersectionObserver ? new IntersectionObserver(onSeen) : null;

  function drawCharts(root) {
    var figures = root.querySelectorAll('script[type="application/json"][data-chart]');
    if (!figures.length) {
      return;
    }
    if (!window.Plotly) {
      loadPlotly();
      return;
    }
    var wanted = {};
    var added = false;
    figures.forEach(function (script) {
      var target = document.getElementById(script.dataset.chart);
      if (!target || target.classList.contains("js-plotly-plot")) {
        return;
      }
      wanted[target.id] = true;
      if (chartQueue.indexOf(script) >= 0 || waiting.indexOf(script) >= 0) {
        return;
      }
      added = true;
      if (inView(target)) {
        chartQueue.push(script);
      } else {
        waiting.push(script);
        if (watcher) {
          watcher.observe(target);
        }
      }
    });
    releaseKeptCharts(wanted);
    if (added) {
      startDrawing();
    }
  }

  function inView(target) {
    var box = target.getBoundingClientRect();
    return box.bottom > 0 && box.top < window.innerHeight;
  }

  function connected(script) {
    return script.isConnected;
  }

  function startDrawing() {
    if (drawing) {
      return;
    }
    drawing = true;
    requestAnimationFrame(function () {
      setTimeout(drawNextChart);
    });
  }

  // the charts in view draw back to back in one task, so one frame paints them all (a
  // frame between each cost a fifth to a third more work), but give way to a keystroke
  // waiting to be handled; where the browser cannot tell (no isInputPending), one a task
  function inputWaiting() {
    var scheduling = navigator.scheduling;
    return !scheduling || !scheduling.isInputPending || scheduling.isInputPending();
  }

  function drawNextChart() {
    do {
      chartQueue = chartQueue.filter(connected);
      var script = chartQueue.shift();
      if (script) {
        plot(script);
        drawnInView += 1;
      }
    } while (chartQueue.length && !inputWaiting());
    if (chartQueue.length) {
      setTimeout(drawNextChart);
      return;
    }
    drawing = false;
    var detail = { drawn: drawnInView, waiting: waiting.filter(connected).length };
    drawnInView = 0;
    document.dispatchEvent(new CustomEvent("charts:drawn", { detail: detail }));
    waitForQuiet();
  }

  // a waiting chart scrolled into view joins the queue
  function onSeen(entries) {
    entries.forEach(function (entry) {
      if (!entry.isIntersecting) {
        return;
      }
      watcher.unobserve(entry.target);
      var script = waiting.filter(function (s) {
        return s.dataset.chart === entry.target.id && s.isConnected;
      })[0];
      if (script) {
        waiting.splice(waiting.indexOf(script), 1);
        chartQueue.push(script);
        startDrawing();
      }
    });
  }

  function waitForQuiet() {
    clearTimeout(quietTimer);
    quietTimer = waiting.length ? setTimeout(drawRest, QUIET_MS) : null;
  }

  // the charts out of view, one a task, while no field is edited
  function drawRest() {
    waiting = waiting.filter(connected);
    var script = waiting.shift();
    if (!script) {
      return;
    }
    unwatch(script);
    plot(script);
    quietTimer = waiting.length ? setTimeout(drawRest) : null;
  }

  function unwatch(script) {
    var target = document.getElementById(script.dataset.chart);
    if (watcher && target) {
      watcher.unobserve(target);
    }
  }

  // every chart not yet drawn, now (the printout needs them all)
  function drawAllCharts() {
    chartQueue
      .splice(0)
      .concat(waiting.splice(0))
      .forEach(function (script) {
        if (script.isConnected) {
          unwatch(script);
          plot(script);
        }
      });
  }

  // a kept chart whose new figure is the one it shows (an edit the chart does not depend
  // on: the stroke for the critical speed) is put back as it is, not drawn again
  function plot(script) {
    var target = document.getElementById(script.dataset.chart);
    if (!target || target.classList.contains("js-plotly-plot")) {
      return;
    }
    var text = script.textContent;
    var kept = keptCharts[target.id];
    if (kept) {
      delete keptCharts[target.id];
      target.replaceWith(kept);
      target = kept;
      if (kept.figureText === text) {
        return;
      }
    }
    var figure = JSON.parse(text);
    var config = Object.assign({}, PLOT_CONFIG, {
      toImageButtonOptions: { format: "png", filename: script.dataset.chart, scale: 2 },
    });
    target.figureText = text;
    if (kept) {
      window.Plotly.react(target, figure.data, figure.layout, config);
    } else {
      window.Plotly.newPlot(target, figure.data, figure.layout, config);
    }
  }

  // A field's error shows once the field has been left or the form submitted (results
  // shown count as a submission, as does a page the server answered with errors): the
  // first keystroke in an empty form says nothing under the fields not yet reached. Each
  // error line keeps the server's message in data-error and shows it only then; its space
  // is reserved (app.css), so no field moves when a message appears or clears. The same
  // holds for the custom screw's form (one of the two is on a page).
  function selectorForm() {
    return document.getElementById("selector") || document.getElementById("custom");
  }

  function isTouched(form, name) {
    var wrapper = document.getElementById("w-" + name);
    return form.classList.contains("submitted") || (!!wrapper && wrapper.classList.contains("touched"));
  }

  function errorLines(form) {
    return form.querySelectorAll("span.error[id^='e-']");
  }

  // the errors an htmx answer listed (#field-errors, swapped out of band) become the lines'
  function takeAnswerErrors(form) {
    var holder = document.getElementById("field-errors");
    if (!holder || holder.hasAttribute("data-applied")) {
      return;
    }
    holder.setAttribute("data-applied", "");
    var errors = {};
    holder.querySelectorAll("[data-error-for]").forEach(function (item) {
      errors[item.dataset.errorFor] = item.textContent;
    });
    errorLines(form).forEach(function (line) {
      line.setAttribute("data-error", errors[line.id.slice(2)] || "");
    });
  }

  function showErrors() {
    var form = selectorForm();
    if (!form) {
      return;
    }
    markAnswered(form);
    takeAnswerErrors(form);
    errorLines(form).forEach(function (line) {
      if (!line.hasAttribute("data-error")) {
        line.setAttribute("data-error", line.textContent);
      }
      var name = line.id.slice(2);
      var text = isTouched(form, name) ? line.getAttribute("data-error") || missing(form, name) : "";
      if (line.textContent !== text) {
        line.textContent = text;
      }
    });
  }

  // a required field left empty before any answer named it
  function missing(form, name) {
    var field = form.elements.namedItem(name);
    return field && field.dataset && field.dataset.missing && !field.value.trim() ? field.dataset.missing : "";
  }

  function onFieldLeft(event) {
    var name = event.target.name;
    var wrapper = name && document.getElementById("w-" + name);
    if (wrapper && !wrapper.classList.contains("touched")) {
      wrapper.classList.add("touched");
      showErrors();
      syncInvalid();
    }
  }

  function onSubmit(event) {
    if (event.target === selectorForm()) {
      event.target.classList.add("submitted");
      showErrors();
      syncInvalid();
    }
  }

  // results on the page count as a submission
  function markAnswered(form) {
    if (document.querySelector("#results .result-head")) {
      form.classList.add("submitted");
    }
  }

  // a page loaded with results, or with the server's errors, was submitted
  function startErrors() {
    var form = selectorForm();
    if (!form) {
      return;
    }
    var answered = Array.prototype.some.call(errorLines(form), function (line) {
      return line.textContent.trim() !== "";
    });
    if (answered) {
      form.classList.add("submitted");
    }
    markAnswered(form);
    form.addEventListener("focusout", onFieldLeft);
  }

  // an answer of errors only under fields not yet reached changes nothing on the page: no
  // banner, no count of fields to correct (its out-of-band status and bar are dropped)
  var quietAnswer = false;

  function isQuiet(response) {
    var form = selectorForm();
    if (!form || form.classList.contains("submitted") || response.indexOf("data-keep-results") < 0) {
      return false;
    }
    var named = /data-error-for="([a-z0-9_]+)"/g;
    var match;
    while ((match = named.exec(response)) !== null) {
      if (isTouched(form, match[1])) {
        return false;
      }
    }
    return true;
  }

  // a field redrawn in new units stays as reached as it was
  function onOobSwap(event) {
    var target = event.detail.target;
    if (!target) {
      return;
    }
    if (quietAnswer && (target.id === "status" || target.id === "result-bar")) {
      event.detail.shouldSwap = false;
    }
    var field = event.detail.fragment.firstElementChild;
    if (target.classList.contains("touched") && field) {
      field.classList.add("touched");
    }
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
    document.querySelectorAll("button.copy-link[hidden], button.copy-order[hidden], button.print-report[hidden]").forEach(function (button) {
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

  // an ordering line's button copies the line beside it
  function onCopyLine(button) {
    var row = button.closest(".order-row");
    var line = row.querySelector(".order-line").textContent.trim();
    var status = row.querySelector(".copy-order-status");
    copyText(line).then(
      function () {
        status.textContent = "Line copied.";
      },
      function () {
        status.textContent = "Select the line and copy it.";
      }
    );
  }

  function onClick(event) {
    var line = event.target.closest("button.copy-order");
    if (line) {
      onCopyLine(line);
      return;
    }
    if (event.target.closest("button.print-report")) {
      window.print();
      return;
    }
    var button = event.target.closest("button.copy-link");
    if (button) {
      onCopy(button);
      return;
    }
    var row = event.target.closest("tbody.candidate > tr.main");
    if (row && !event.target.closest("a, button, summary, input, select, label")) {
      var detail = row.parentElement.querySelector("details.detail");
      if (detail) {
        detail.open = !detail.open;
      }
    }
  }

  // a result's <details class="detail"> loads its body when first opened, from the link it
  // holds for a reader without JavaScript (the same /detail URL, answered as a fragment)
  // (the rejected list likewise, from /rejected; a series of the catalog, from /catalog/{id})
  var LAZY_DETAILS = "details.detail, details.rejected, details.series";

  function onToggle(event) {
    var detail = event.target;
    if (!detail.matches || !detail.matches(LAZY_DETAILS) || !detail.open) {
      return;
    }
    var body = detail.querySelector(":scope > .pending");
    var link = body && body.querySelector("a[href]");
    if (!link || !window.htmx || detail.hasAttribute("data-asked")) {
      return;
    }
    detail.setAttribute("data-asked", "");
    window.htmx.ajax("GET", link.getAttribute("href"), { source: detail, target: body, swap: "outerHTML" });
  }

  function markLoading(event) {
    var detail = event.detail.elt;
    if (detail.matches(LAZY_DETAILS)) {
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

  // the form's requests queue (hx-sync "queue last") rather than abort one another, and
  // an answer to values typed over since it was asked for is dropped: the newer one follows
  var edits = 0;

  function countEdit(event) {
    if (event.target.form === selectorForm()) {
      edits += 1;
      clearTimeout(quietTimer);
      quietTimer = null;
    }
  }

  function stampRequest(event) {
    if (event.detail.elt === selectorForm()) {
      event.detail.xhr.selectorEdits = edits;
    }
  }

  // a field being retyped answers with errors only: keep the last results, dimmed
  function keepStaleResults(event) {
    var target = event.detail.target;
    if (!target || target.id !== "results") {
      return;
    }
    var asked = event.detail.xhr.selectorEdits;
    if (asked !== undefined && asked !== edits) {
      event.detail.shouldSwap = false;
      return;
    }
    var keep = event.detail.serverResponse.indexOf("data-keep-results") !== -1;
    var note = target.querySelector(".stale-note");
    quietAnswer = isQuiet(event.detail.serverResponse);
    if (quietAnswer) {
      event.detail.swapOverride = "none";
      event.detail.ignoreTitle = true;
    } else if (keep && note) {
      event.detail.swapOverride = "none";
      target.classList.add("stale");
      note.hidden = false;
    } else {
      target.classList.remove("stale");
      // the old charts, or the slot still holding their place
      var charts = target.querySelector("section.charts, #charts-slot");
      chartsHeight = charts ? charts.offsetHeight : 0;
      var url = chartsUrl(event.detail.serverResponse);
      if (url) {
        askCharts(url);
      }
      keepCharts(target);
    }
  }

  // the new results' charts arrive after them (/charts): until then their place keeps the
  // old charts' height, so nothing below them moves, nor the page under the reader
  var chartsHeight = 0;

  // an answer's charts are asked for (/charts, its query) as soon as the answer arrives, so
  // the server computes them while the table is swapped in and painted; they take their
  // place once both are done
  var chartsAsked = {};

  // a refused or failed ask is forgotten, so the next ask is a new request; its error
  // carries how long to wait first (the answer's Retry-After, else CHARTS_RETRY_S)
  var CHARTS_RETRY_S = 1;
  var CHARTS_RETRY_MOST_S = 30;
  var CHARTS_TRIES = 5;

  function askCharts(url) {
    if (!chartsAsked[url]) {
      chartsAsked = {};
      chartsAsked[url] = fetch(url, { headers: { "HX-Request": "true" } })
        .then(function (response) {
          if (response.ok) {
            return response.text();
          }
          var error = new Error(response.statusText);
          error.retryAfterS = Number(response.headers.get("Retry-After")) || CHARTS_RETRY_S;
          throw error;
        })
        .catch(function (error) {
          delete chartsAsked[url];
          throw error;
        });
    }
    return chartsAsked[url];
  }

  function chartsUrl(answer) {
    var found = /id="charts-slot"[^>]* data-src="([^"]+)"/.exec(answer);
    return found ? found[1].replace(/&amp;/g, "&") : null;
  }

  function loadCharts() {
    var slot = document.getElementById("charts-slot");
    if (!slot || slot.hasAttribute("data-asked")) {
      return;
    }
    slot.setAttribute("data-asked", "");
    askCharts(slot.dataset.src).then(
      function (html) {
        var holder = document.createElement("div");
        holder.innerHTML = html;
        var section = holder.querySelector("section.charts");
        if (slot.isConnected && section) {
          slot.replaceWith(section);
          drawCharts(document);
        }
      },
      function (error) {
        slot.removeAttribute("data-asked");
        var tries = Number(slot.dataset.tries || 0) + 1;
        slot.dataset.tries = String(tries);
        if (tries < CHARTS_TRIES) {
          var waitS = Math.min(error.retryAfterS || CHARTS_RETRY_S, CHARTS_RETRY_MOST_S);
          setTimeout(loadCharts, waitS * 1000);
        }
      }
    );
  }

  function holdChartsPlace() {
    var slot = document.getElementById("charts-slot");
    if (slot && chartsHeight) {
      slot.style.minHeight = chartsHeight + "px";
    }
    chartsHeight = 0;
  }

  // the swap replaces the charts: each drawn chart is taken out of the old results first
  // (htmx would otherwise walk its thousands of SVG nodes one by one while cleaning up)
  // and kept to be redrawn with the new figure by Plotly.react, about three times faster
  // than drawing it anew; one the new answer has no figure for is purged, which drops its
  // window resize listener (kept for ever otherwise)
  var keptCharts = {};

  function keepCharts(target) {
    releaseKeptCharts();
    eachChart(function (chart) {
      if (target.contains(chart)) {
        chart.remove();
        keptCharts[chart.id] = chart;
      }
    });
  }

  function releaseKeptCharts(wanted) {
    Object.keys(keptCharts).forEach(function (id) {
      if (!wanted || !wanted[id]) {
        window.Plotly.purge(keptCharts[id]);
        delete keptCharts[id];
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
      drawAllCharts();
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

  // the new errors and their aria-invalid in the swap's own task, before it is painted
  // an HTMX answer writes each cell's label (shown above its value on a phone) once, on
  // its column's heading: each cell takes its heading's
  function labelCells() {
    document.querySelectorAll("table.candidates").forEach(function (table) {
      var heads = table.querySelectorAll("thead th");
      table.querySelectorAll("tr.main").forEach(function (row) {
        Array.prototype.forEach.call(row.children, function (cell, i) {
          var label = heads[i] && heads[i].dataset.label;
          if (label && cell.tagName === "TD" && !cell.hasAttribute("data-label")) {
            cell.setAttribute("data-label", label);
          }
        });
      });
    });
  }

  function afterSwap() {
    labelCells();
    holdChartsPlace();
    loadCharts();
    quietAnswer = false;
    showErrors();
    syncInvalid();
  }

  document.addEventListener("DOMContentLoaded", function () {
    loadCharts();
    startErrors();
    refresh();
  });
  document.addEventListener("htmx:afterSwap", afterSwap);
  document.addEventListener("htmx:oobBeforeSwap", onOobSwap);
  document.addEventListener("submit", onSubmit, true);
  document.addEventListener("htmx:afterSettle", refresh);
  document.addEventListener("click", onClick);
  document.addEventListener("toggle", onToggle, true);
  document.addEventListener("htmx:beforeSwap", keepStaleResults);
  document.addEventListener("htmx:beforeRequest", markLoading);
  document.addEventListener("htmx:beforeRequest", stampRequest);
  document.addEventListener("input", countEdit, true);
  document.addEventListener("htmx:afterRequest", markLoading);
  window.addEventListener("beforeprint", dateReport);
  window.matchMedia("print").addEventListener("change", onPrintMedia);
})();
