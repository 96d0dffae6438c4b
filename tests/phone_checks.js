// What a reader on a phone meets, found from the page's own layout (tests/report_phone_test.py
// and tests/console_browser_test.py run it as a script's body). One line per problem: a word or
// number split across two lines, text under 12 px as drawn (a chart's label at its drawing's
// scale), text cut off at the screen's edge or by a box that hides what overflows, a chart's
// label outside its drawing or over another.
const problems = [];
const viewport = document.documentElement.clientWidth;
const describe = (el, text) =>
  el.tagName.toLowerCase() + (el.id ? "#" + el.id : "") + ' "' + text.trim().slice(0, 40) + '"';
const shown = (el) => {
  const st = getComputedStyle(el);
  return st.display !== "none" && st.visibility !== "hidden" && el.getClientRects().length > 0;
};
// Text inside a box that scrolls sideways may run past the screen: the reader scrolls the box.
const inScroller = (el) => {
  for (let e = el.parentElement; e && e !== document.body; e = e.parentElement) {
    const o = getComputedStyle(e).overflowX;
    if (o === "auto" || o === "scroll") return true;
  }
  return false;
};
const range = document.createRange();
const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT);
for (let node = walker.nextNode(); node; node = walker.nextNode()) {
  const text = node.textContent;
  const el = node.parentElement;
  if (!text.trim() || !el || el.closest("script,style,noscript,title") || !shown(el)) continue;
  let size = parseFloat(getComputedStyle(el).fontSize);
  if (el.closest("svg") && el.getScreenCTM) {
    const m = el.getScreenCTM();
    if (m) size *= Math.hypot(m.a, m.b);
  }
  if (size < 11.95) problems.push("text of " + size.toFixed(1) + " px: " + describe(el, text));
  // A word on two lines has fragments at two heights; a hyphen or a slash may break a line.
  const words = /[^\s\-\/\u2010\u2011]+/g;
  for (let m = words.exec(text); m; m = words.exec(text)) {
    range.setStart(node, m.index);
    range.setEnd(node, m.index + m[0].length);
    const tops = new Set();
    for (const r of range.getClientRects()) if (r.width > 0) tops.add(Math.round(r.top));
    if (tops.size > 1) problems.push('word split across lines: "' + m[0] + '" in ' + describe(el, text));
  }
  range.selectNodeContents(node);
  const r = range.getBoundingClientRect();
  if (r.width === 0) continue;
  if (!inScroller(el) && (r.right > viewport + 1 || r.left < -1))
    problems.push("cut off at the screen's edge: " + describe(el, text));
  for (let e = el; e && e !== document.body; e = e.parentElement) {
    const st = getComputedStyle(e);
    if (st.overflowX !== "hidden" && st.overflowX !== "clip") continue;
    const b = e.getBoundingClientRect();
    if (r.right > b.right + 1 || r.left < b.left - 1)
      problems.push("cut off by its box: " + describe(el, text));
    break;
  }
}
for (const svg of document.querySelectorAll("svg")) {
  if (!shown(svg)) continue;
  const box = svg.getBoundingClientRect();
  const labels = [];
  for (const t of svg.querySelectorAll("text"))
    if (t.textContent.trim() && shown(t)) labels.push([t, t.getBoundingClientRect()]);
  for (const [t, r] of labels)
    if (r.left < box.left - 1 || r.right > box.right + 1 || r.top < box.top - 1 ||
        r.bottom > box.bottom + 1)
      problems.push("label outside its chart: " + describe(t, t.textContent));
  for (let i = 0; i < labels.length; ++i) {
    for (let j = i + 1; j < labels.length; ++j) {
      const a = labels[i][1], b = labels[j][1];
      const w = Math.min(a.right, b.right) - Math.max(a.left, b.left);
      const h = Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top);
      if (w > 1 && h > 1)
        problems.push("labels over one another: " + describe(labels[i][0], labels[i][0].textContent) +
                      ' and "' + labels[j][0].textContent.trim().slice(0, 40) + '"');
    }
  }
}
// Labels a chart draws on its canvas (report/chart.cpp keeps where: data-marks).
for (const el of document.querySelectorAll("[data-marks]")) {
  if (!shown(el)) continue;
  const box = el.getBoundingClientRect();
  const marks = JSON.parse(el.dataset.marks);
  marks.forEach(([x, y, w, h], i) => {
    if (x < -1 || y < -1 || x + w > box.width + 1 || y + h > box.height + 1 ||
        box.left + x + w > viewport + 1)
      problems.push("chart label " + (i + 1) + " cut off in #" + el.id);
    for (let j = i + 1; j < marks.length; ++j) {
      const [u, v, p, q] = marks[j];
      if (Math.min(x + w, u + p) - Math.max(x, u) > 1 && Math.min(y + h, v + q) - Math.max(y, v) > 1)
        problems.push("chart labels " + (i + 1) + " and " + (j + 1) + " over one another in #" + el.id);
    }
  });
}
return [...new Set(problems)];
