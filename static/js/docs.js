// Starts Swagger UI on /docs. A static file rather than an inline script, so the
// Content-Security-Policy (script-src 'self') holds; the OpenAPI URL comes from the page.
//
// Two fixes for WCAG 2.1 from outside the vendored bundle, through Swagger UI's plugin
// system (components replaced or wrapped by name):
// - it draws each operation's path as a link (its DeepLink component) inside the button
//   that opens the operation: a control inside a control, which assistive technology
//   cannot reach on its own (axe: nested-interactive, WCAG 4.1.2). Drawn here as plain
//   text; the deep-linking plugin still writes and reads the URL's fragment
//   (#/tag/operationId) when an operation opens, so a link to one still works;
// - the API's title, version and description stand outside every landmark, and the
//   operations' tags (h3) follow the title (h1) with no h2: the title block becomes a
//   named region and an "Operations" heading (visually hidden) leads the operations.
// - the controls Swagger UI draws for a parameter (an enum's select, an array's or
//   object's text box), the request body's text box and the select of named examples
//   (drawn when an operation has more than one) carry no label (WCAG 1.3.1, 4.1.2;
//   axe: label, select-name): each is named after its parameter ("limit (query)"),
//   "Request body" or "Examples, request body" ("Examples, response 200") as it is
//   drawn, and each operation's responses table (a region) after its operation, so
//   that no two regions share a name (axe: landmark-unique).
// The code samples use the "idea" highlighting theme: the default "agate" draws numbers
// in #d36363 on #333 (3.45:1, under the 4.5:1 of WCAG 1.4.3).
document.addEventListener("DOMContentLoaded", function () {
  var root = document.getElementById("swagger-ui");

  function accessible(system) {
    var h = system.React.createElement;
    return {
      components: {
        DeepLink: function (props) {
          return h("span", null, props.text);
        },
      },
      wrapComponents: {
        InfoContainer: function (Original) {
          return function (props) {
            return h("div", { role: "region", "aria-label": "About this API" }, h(Original, props));
          };
        },
        operations: function (Original) {
          return function (props) {
            return h(
              system.React.Fragment,
              null,
              h("h2", { className: "visually-hidden" }, "Operations"),
              h(Original, props)
            );
          };
        },
      },
    };
  }

  function labelControls(scope) {
    scope.querySelectorAll("input, select, textarea").forEach(function (control) {
      if (control.hasAttribute("aria-label") || control.labels.length || control.title) {
        return;
      }
      var row = control.closest("tr[data-param-name]");
      if (control.classList.contains("examples-select-element")) {
        var response = control.closest("tr.response[data-code]");
        control.setAttribute(
          "aria-label",
          response ? "Examples, response " + response.dataset.code : "Examples, request body"
        );
      } else if (row) {
        control.setAttribute("aria-label", row.dataset.paramName + " (" + row.dataset.paramIn + ")");
      } else if (control.closest(".body-param")) {
        control.setAttribute("aria-label", "Request body");
      }
    });
  }

  function nameRegions(scope) {
    scope.querySelectorAll("[role=region]:not([aria-label])").forEach(function (region) {
      var operation = region.closest(".opblock");
      var summary = operation && operation.querySelector(".opblock-summary-path");
      var method = operation && operation.querySelector(".opblock-summary-method");
      if (summary && method) {
        var kind = region.classList.contains("live-responses-table") ? "Server response" : "Responses";
        region.setAttribute("aria-label", kind + ", " + method.textContent + " " + summary.textContent);
      }
    });
  }

  new MutationObserver(function () {
    labelControls(root);
    nameRegions(root);
  }).observe(root, { childList: true, subtree: true });

  window.ui = SwaggerUIBundle({
    url: root.dataset.openapiUrl,
    dom_id: "#swagger-ui",
    layout: "BaseLayout",
    deepLinking: true,
    showExtensions: true,
    showCommonExtensions: true,
    validatorUrl: null,
    presets: [SwaggerUIBundle.presets.apis, SwaggerUIBundle.SwaggerUIStandalonePreset],
    syntaxHighlight: { activated: true, theme: "idea" },
    plugins: [accessible],
  });
});
