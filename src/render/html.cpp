// SPDX-License-Identifier: Apache-2.0
#include <preimage/render/html.hpp>

#include <preimage/error.hpp>
#include <preimage/render/svg.hpp>

#include <fstream>

namespace preimage::render {

HtmlReport::HtmlReport(std::string title) : title_(std::move(title)) {}

void HtmlReport::close_list() {
  if (in_list_) body_ += "</ul>\n", in_list_ = false;
}

void HtmlReport::section(const std::string& heading) {
  close_list();
  body_ += "<h2>" + escape(heading) + "</h2>\n";
}

void HtmlReport::paragraph(const std::string& text) {
  close_list();
  body_ += "<p>" + escape(text) + "</p>\n";
}

void HtmlReport::result(const std::string& text) {
  if (!in_list_) body_ += "<ul>\n", in_list_ = true;
  body_ += "<li>" + escape(text) + "</li>\n";
}

void HtmlReport::figure(const std::string& svg, const std::string& caption) {
  close_list();
  body_ += "<figure>\n" + svg + "<figcaption>" + escape(caption) + "</figcaption>\n</figure>\n";
}

namespace {
// The report's only script: no network, no library. Every figure pans (drag) and zooms
// (wheel, around the pointer; double-click resets) through its root SVG's viewBox. A
// figure holding paths drawn by SvgCanvas::path (groups tagged data-path="first step")
// gets a step slider: at step k each path shows its points up to k, with a marker at
// its head; arrows show only at the last step. Script errors are written into the page
// (data-script-errors on <body> and a visible line), so a headless browser test sees them;
// "#selftest" in the URL exercises every control and records the result in
// data-selftest.
constexpr const char* kScript = R"JS(
(function () {
  'use strict';
  var errors = [];
  function report(msg) {
    errors.push(msg);
    document.body.setAttribute('data-script-errors', errors.join(' | '));
    var p = document.getElementById('script-errors');
    if (p) { p.textContent = 'Script error: ' + errors.join(' | '); p.hidden = false; }
  }
  window.addEventListener('error', function (e) { report(e.message + ' at ' + e.lineno + ':' + e.colno); });
  function box(svg) { return svg.getAttribute('viewBox').split(/[ ,]+/).map(Number); }
  function setBox(svg, b) { svg.setAttribute('viewBox', b.join(' ')); }
  function panZoom(svg) {
    var home = box(svg), drag = null;
    svg.style.cursor = 'grab';
    svg.style.touchAction = 'none';
    function toUser(ev) {
      var r = svg.getBoundingClientRect(), b = box(svg);
      return [b[0] + (ev.clientX - r.left) / r.width * b[2], b[1] + (ev.clientY - r.top) / r.height * b[3]];
    }
    svg.addEventListener('wheel', function (ev) {
      ev.preventDefault();
      var b = box(svg), p = toUser(ev), f = ev.deltaY < 0 ? 0.8 : 1.25;
      setBox(svg, [p[0] - (p[0] - b[0]) * f, p[1] - (p[1] - b[1]) * f, b[2] * f, b[3] * f]);
    }, { passive: false });
    svg.addEventListener('pointerdown', function (ev) {
      if (ev.target.closest && ev.target.closest('input')) return;
      drag = { x: ev.clientX, y: ev.clientY, b: box(svg) };
      svg.style.cursor = 'grabbing';
      if (svg.setPointerCapture) svg.setPointerCapture(ev.pointerId);
    });
    svg.addEventListener('pointermove', function (ev) {
      if (!drag) return;
      var r = svg.getBoundingClientRect(), b = drag.b;
      setBox(svg, [b[0] - (ev.clientX - drag.x) / r.width * b[2], b[1] - (ev.clientY - drag.y) / r.height * b[3], b[2], b[3]]);
    });
    function end() { drag = null; svg.style.cursor = 'grab'; }
    svg.addEventListener('pointerup', end);
    svg.addEventListener('pointercancel', end);
    svg.addEventListener('dblclick', function () { setBox(svg, home.slice()); });
    return home;
  }
  function parsePoints(text) {
    return text.trim().split(/\s+/).filter(function (s) { return s.length; });
  }
  function stepper(fig, groups) {
    var paths = [], last = 0, ns = 'http://www.w3.org/2000/svg';
    groups.forEach(function (g) {
      var line = g.querySelector('polyline');
      if (!line) return;
      var pts = parsePoints(line.getAttribute('points')), first = Number(g.getAttribute('data-path')) || 0;
      var head = document.createElementNS(ns, 'circle');
      head.setAttribute('r', '5');
      head.setAttribute('fill', line.getAttribute('stroke') || '#222');
      head.setAttribute('stroke', '#fff');
      head.setAttribute('stroke-width', '1.5');
      head.style.display = 'none';
      g.appendChild(head);
      paths.push({ g: g, line: line, pts: pts, first: first, head: head, arrows: g.querySelector('[data-arrows]') });
      last = Math.max(last, first + pts.length - 1);
    });
    if (!paths.length || last < 1) return null;
    var row = document.createElement('div'), input = document.createElement('input'), label = document.createElement('span');
    row.className = 'stepper';
    input.type = 'range'; input.min = 0; input.max = last; input.value = last;
    input.setAttribute('aria-label', 'step along the paths');
    row.appendChild(document.createTextNode('step '));
    row.appendChild(input);
    row.appendChild(label);
    fig.insertBefore(row, fig.querySelector('figcaption'));
    function show(k) {
      paths.forEach(function (p) {
        var n = Math.max(0, Math.min(p.pts.length, k - p.first + 1));
        p.line.setAttribute('points', p.pts.slice(0, n).join(' '));
        p.line.style.display = n >= 2 ? '' : 'none';
        if (p.arrows) p.arrows.style.display = k >= last ? '' : 'none';
        var active = n >= 1 && k < last && k - p.first <= p.pts.length - 1;
        p.head.style.display = active ? '' : 'none';
        if (active) {
          var xy = p.pts[n - 1].split(',');
          p.head.setAttribute('cx', xy[0]);
          p.head.setAttribute('cy', xy[1]);
        }
      });
      label.textContent = ' ' + k + ' of ' + last;
    }
    input.addEventListener('input', function () { show(Number(input.value)); });
    show(last);
    return { input: input, paths: paths, last: last };
  }
  var figures = [], steppers = [];
  document.querySelectorAll('figure').forEach(function (fig) {
    var svg = fig.querySelector(':scope > svg');
    if (!svg || !svg.getAttribute('viewBox')) return;
    figures.push({ svg: svg, home: panZoom(svg) });
    var s = stepper(fig, Array.prototype.slice.call(svg.querySelectorAll('g[data-path]')));
    if (s) steppers.push(s);
  });
  if (location.hash === '#selftest') {
    var bad = [];
    figures.forEach(function (f, i) {
      var r = f.svg.getBoundingClientRect();
      f.svg.dispatchEvent(new WheelEvent('wheel', { deltaY: -100, clientX: r.left + r.width / 2, clientY: r.top + r.height / 2, bubbles: true, cancelable: true }));
      if (box(f.svg)[2] >= f.home[2]) bad.push('figure ' + i + ' did not zoom');
      f.svg.dispatchEvent(new MouseEvent('dblclick', { bubbles: true }));
      if (box(f.svg).join(' ') !== f.home.join(' ')) bad.push('figure ' + i + ' did not reset');
    });
    steppers.forEach(function (s, i) {
      [0, Math.floor(s.last / 2), s.last].forEach(function (k) {
        s.input.value = k;
        s.input.dispatchEvent(new Event('input'));
        s.paths.forEach(function (p) {
          var want = Math.max(0, Math.min(p.pts.length, k - p.first + 1));
          if (parsePoints(p.line.getAttribute('points')).length !== want) bad.push('slider ' + i + ' step ' + k);
        });
      });
    });
    document.body.setAttribute('data-selftest', (bad.length ? 'failed: ' + bad.join('; ') : 'ok') + ' (' + figures.length +
      ' figures, ' + steppers.length + ' sliders)');
  }
  document.body.setAttribute('data-ready', 'yes');
})();
)JS";
}  // namespace

std::string HtmlReport::str() const {
  std::string out = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + escape(title_) +
                    "</title>\n<style>body{font-family:sans-serif;max-width:60em;margin:2em auto;padding:0 1em;color:#222}"
                    "figure{margin:1em 0}figure>svg{max-width:100%;height:auto;border:1px solid #eee}"
                    "figcaption{color:#555;font-size:90%}h2{border-bottom:1px solid #ccc}"
                    ".stepper{font-size:90%;color:#333}.stepper input{width:60%;vertical-align:middle}"
                    "#script-errors{color:#b00020;font-weight:bold}</style>\n"
                    "</head>\n<body>\n<h1>" + escape(title_) + "</h1>\n"
                    "<p id=\"script-errors\" hidden></p>\n"
                    "<p>Figures: drag to pan, scroll to zoom, double-click to reset; a slider steps along the paths "
                    "of runs.</p>\n" + body_;
  if (in_list_) out += "</ul>\n";
  out += "<script>" + std::string(kScript) + "</script>\n</body>\n</html>\n";
  return out;
}

void HtmlReport::save(const std::string& path) const {
  std::ofstream f(path);
  f << str();
  if (!f) throw InputError(path + ": cannot write file");
}

}  // namespace preimage::render
