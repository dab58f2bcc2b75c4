// The ordering line's copy button: shown once this script runs (without it the line is
// plain selectable text), it puts the line beside it on the clipboard.
(function () {
  "use strict";

  function reveal() {
    document.querySelectorAll("button.copy-order[hidden]").forEach(function (button) {
      button.hidden = false;
    });
  }

  function fallbackCopy(text) {
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

  function copy(text) {
    if (navigator.clipboard && window.isSecureContext) {
      return navigator.clipboard.writeText(text).catch(function () {
        return fallbackCopy(text);
      });
    }
    return fallbackCopy(text);
  }

  function onClick(event) {
    var button = event.target.closest("button.copy-order");
    if (!button) {
      return;
    }
    var row = button.closest(".order-row");
    var line = row.querySelector(".order-line").textContent.trim();
    var status = row.querySelector(".copy-order-status");
    copy(line).then(
      function () {
        status.textContent = "Line copied.";
      },
      function () {
        status.textContent = "Select the line and copy it.";
      }
    );
  }

  document.addEventListener("DOMContentLoaded", reveal);
  document.addEventListener("htmx:afterSettle", reveal);
  document.addEventListener("click", onClick);
})();
