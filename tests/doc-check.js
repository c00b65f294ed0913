// doc-check.js -- run by tests/doc-browser.sh in headless Chromium, in a page
// that holds every page of make doc in an iframe.  Once all have loaded
// (images too), it checks each and writes one line per problem, then
// "checked N pages, M links, K images, F formulas", into the element
// "result" at the top.
"use strict";
const problems = [];
const fetched = new Map();           // file URL -> Document (null: missing)
let nlinks = 0, nimages = 0, nmath = 0, nprog = 0;

function load(url) {
  if (!fetched.has(url)) {
    let doc = null;
    try {
      const x = new XMLHttpRequest();
      x.open("GET", url, false);
      x.send();
      if (x.responseText !== null)
        doc = new DOMParser().parseFromString(x.responseText, "text/html");
    } catch (e) { doc = null; }
    fetched.set(url, doc);
  }
  return fetched.get(url);
}

// text outside code, maths and scripts: no "$" and no TeX command left
function rawText(node, page) {
  for (const c of node.childNodes) {
    if (c.nodeType === Node.TEXT_NODE) {
      const t = c.textContent;
      const m = t.match(/\$|\\[A-Za-z]+|@sect/);
      if (m) {
        const i = Math.max(0, m.index - 30);
        problems.push(page + ": raw TeX in the text: ..." +
                      t.substr(i, 60).replace(/\s+/g, " ") + "...");
      }
    } else if (c.nodeType === Node.ELEMENT_NODE &&
               !/^(pre|code|math|script|style)$/i.test(c.localName)) {
      rawText(c, page);
    }
  }
}

function checkPage(frame) {
  const doc = frame.contentDocument, win = frame.contentWindow;
  const page = frame.getAttribute("src");
  if (!doc || !doc.body || !doc.querySelector("main")) {
    problems.push(page + ": did not load");
    return;
  }
  rawText(doc.body, page);
  for (const m of doc.querySelectorAll("math")) {
    nmath++;
    const r = m.getBoundingClientRect();
    if (!(m instanceof win.MathMLElement) || r.width <= 0 || r.height <= 0)
      problems.push(page + ": formula not rendered: " + m.textContent.substr(0, 40));
    if (m.querySelector("merror"))
      problems.push(page + ": formula with an error: " + m.textContent.substr(0, 40));
  }
  for (const s of doc.querySelectorAll(".math"))
    if (!s.querySelector("math"))
      problems.push(page + ": TeX left as text: " + s.textContent.substr(0, 40));
  for (const img of doc.querySelectorAll("img")) {
    nimages++;
    const src = img.getAttribute("src");
    if (!img.complete || img.naturalWidth === 0)
      problems.push(page + ": image does not load: " + src);
    if (!(img.getAttribute("alt") || "").trim())
      problems.push(page + ": image without alt text: " + src);
    // a figure: the image links to itself (full size), a caption under it
    const fig = img.closest(".figure");
    const link = img.closest("a");
    if (!fig || !fig.querySelector(".caption") ||
        !fig.querySelector(".caption").textContent.trim())
      problems.push(page + ": image without a caption: " + src);
    if (!link || link.getAttribute("href") !== src)
      problems.push(page + ": image not a link to its full size: " + src);
    // at most two panels side by side: no image in a table
    if (img.closest("table"))
      problems.push(page + ": image in a table (panels too small): " + src);
  }
  // a commented program: text and code, no comment markers left
  if (/example\.c\.html$/.test(page)) {
    nprog++;
    if (doc.querySelectorAll("pre code").length < 3 || doc.querySelectorAll("h2").length < 1)
      problems.push(page + ": not a commented program (code blocks, headings)");
    for (const p of doc.querySelectorAll("main > p"))
      if (/^\s*(\/\*|\*\/|\/\/)/.test(p.textContent))
        problems.push(page + ": a comment marker left in the text: " + p.textContent.substr(0, 40));
  }
  for (const a of doc.querySelectorAll("a[href]")) {
    const href = a.getAttribute("href");
    if (/^(https?|mailto):/.test(href)) continue;   // no network here
    nlinks++;
    const u = new URL(a.href);
    if (u.protocol !== "file:") {
      problems.push(page + ": link neither to a file nor to the web: " + href);
      continue;
    }
    const frag = decodeURIComponent(u.hash.substr(1));
    u.hash = "";
    const target = u.href === doc.URL.split("#")[0] ? doc : load(u.href);
    if (!target)
      problems.push(page + ": link to a missing file: " + href);
    else if (frag && !target.getElementById(frag))
      problems.push(page + ": link to a missing anchor: " + href);
  }
}

window.addEventListener("load", () => {
  const frames = document.querySelectorAll("iframe");
  for (const f of frames) checkPage(f);
  if (nprog < 10)
    problems.push("only " + nprog + " commented programs (example.c.html)");
  problems.push("checked " + frames.length + " pages, " + nlinks + " links, " +
                nimages + " images, " + nmath + " formulas, " + nprog + " programs");
  document.getElementById("result").textContent = problems.join("\n") + "\nDONE\n";
});
