"""The parts of a result that load after its table, in real Chromium: the charts (from
/charts once the table is in; those in view drawn first, the others when scrolled to or
once no field has been edited for half a second) and the cells' phone labels, which an
HTMX answer writes once on each column's heading."""

from typing import Any

AXIS = "load=100&lead=10&speed=50&length=500"
#: the page's own record of each "charts:drawn": how many charts in view it drew
DRAWN = """() => {
  window.__drawn = [];
  document.addEventListener('charts:drawn', (e) => window.__drawn.push(e.detail));
}"""
#: each screw's load torque on the torque chart (its third trace)
LOAD_TORQUE = """() => {
  const load = document.getElementById('chart-torque').data[2];
  return Object.fromEntries(load.x.map((id, i) => [id, load.y[i]]));
}"""
CELL_LABELS = """() => [...document.querySelectorAll('table.candidates tr.main')].map(
  row => [...row.querySelectorAll('td')].map(td => td.dataset.label || ''))"""


def in_view(page: Any) -> list[str]:
    return list(
        page.eval_on_selector_all(
            ".chart",
            """charts => charts.filter(c => {
              const b = c.getBoundingClientRect();
              return b.bottom > 0 && b.top < innerHeight;
            }).map(c => c.id)""",
        )
    )


def test_charts_arrive_after_the_table_and_draw_in_view_first(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    page.goto(f"{live_server}/?{AXIS}")
    page.wait_for_selector("tbody.candidate")
    # out of view below the form, every chart is still drawn once the page is quiet
    page.wait_for_function(
        "() => [...document.querySelectorAll('.chart')].every(c => c.querySelector('.main-svg'))"
    )
    before = page.evaluate(LOAD_TORQUE)
    page.evaluate(DRAWN)
    page.fill("#f-load", "150")
    page.evaluate("() => document.querySelector('section.charts').scrollIntoView()")
    # a pass begun before the new answer was swapped in draws none of its charts, which
    # the swap took out of the page (drawn 0): the first pass that draws is the answer's
    page.wait_for_function("() => window.__drawn.some(d => d.drawn > 0)")
    shown = in_view(page)
    assert shown, "no chart in view after scrolling to the charts"
    drawn = page.evaluate("() => window.__drawn.find(d => d.drawn > 0)")
    # every chart in view was drawn (or put back unchanged) for the new answer
    assert 1 <= drawn["drawn"] <= len(shown)
    for chart in shown:
        assert page.locator(f"#{chart} .main-svg").count() >= 1
    # a chart out of view draws when scrolled to; the torque chart answers the new load:
    # its load torque is 1.5 times the old (F l / (2 pi eta) is proportional to F)
    page.evaluate("() => document.getElementById('chart-torque').scrollIntoView()")
    page.wait_for_function("() => document.getElementById('chart-torque').data")
    after = page.evaluate(LOAD_TORQUE)
    both = set(before) & set(after)
    assert both
    for screw in both:
        assert abs(after[screw] / before[screw] - 1.5) < 0.01, screw
    assert console_errors == []


def test_an_htmx_answer_labels_its_cells_as_a_full_page_does(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    page.set_viewport_size({"width": 390, "height": 844})
    page.goto(f"{live_server}/?load=150&lead=10&speed=50&length=500")
    page.wait_for_selector("tbody.candidate")
    full = page.evaluate(CELL_LABELS)
    assert full and all(all(labels) for labels in full)
    page.goto(f"{live_server}/?load=100&lead=10&speed=50&length=500")
    page.wait_for_selector("tbody.candidate")
    page.fill("#f-load", "150")
    page.wait_for_function("() => location.search.includes('load=150')")
    page.wait_for_selector("tbody.candidate")
    assert page.evaluate(CELL_LABELS) == full
    assert console_errors == []


#: app.js's QUIET_MS and a little: the charts out of view are drawn by then
QUIET_MS = 800
#: each chart drawn (Plotly.react or newPlot) with the number of frames run before it
FRAMES = """() => {
  window.__frames = 0;
  window.__draws = [];
  const tick = () => { window.__frames += 1; requestAnimationFrame(tick); };
  requestAnimationFrame(tick);
  for (const name of ['react', 'newPlot']) {
    const draw = Plotly[name];
    Plotly[name] = function (target) {
      window.__draws.push([target.id, window.__frames]);
      return draw.apply(this, arguments);
    };
  }
}"""


def test_the_charts_in_view_are_painted_in_one_frame(
    page: Any, live_server: str, console_errors: list[str]
) -> None:
    """The charts in view draw back to back (no frame painted between them, which would
    cost the page a layout and a paint each), giving way only to a keystroke waiting."""
    page.goto(f"{live_server}/?{AXIS}")
    page.wait_for_selector("#chart-torque .main-svg")
    page.evaluate("() => document.querySelector('section.charts').scrollIntoView()")
    page.wait_for_function(
        "() => [...document.querySelectorAll('.chart')].every(c => c.querySelector('svg'))"
    )
    page.wait_for_timeout(QUIET_MS)
    page.evaluate(DRAWN)
    page.evaluate(FRAMES)
    # a new speed changes every chart: the critical speed's operating points too
    page.fill("#f-speed", "80")
    page.evaluate("() => document.querySelector('section.charts').scrollIntoView()")
    page.wait_for_function("() => window.__drawn.length > 0")
    drawn = page.evaluate("() => window.__drawn[0].drawn")
    draws = page.evaluate("() => window.__draws")[:drawn]
    assert drawn >= 2 and len(draws) == drawn, (drawn, draws)
    assert len({frames for _, frames in draws}) == 1, draws
    assert console_errors == []
