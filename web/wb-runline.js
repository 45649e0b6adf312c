// What a program's opening comments ask to be run with, as the examples' RUN lines write it
// (`(RUN: ./build/ncurve run examples/custom-cycle.nc --lib macros --param 6050=102)`), when the page
// runs it otherwise: a note under the editor says so.
// - `--machine NAME`: when it is a shipped profile and not the one chosen, a button chooses it
//   (picking 4-axis.nc from the menu on a 3-axis mill tells why it alarms, PS0009).
// - `--param`, `--set`, `--lib FOLDER`: those not in the Settings (wb-settings.js), and one button
//   that puts them there (a parameter or variable of the same number replaced, the folder ticked);
//   a folder that is none of the server's --lib folders cannot be chosen by the page: the note says
//   to start the server with `--lib FOLDER`.
//   NcurveRunLine.asked(text) -> 'fanuc-4axis-helicoid' or null
//   NcurveRunLine.options(text) -> {lib: ['macros'], param: ['6050=102'], set: ['#100=2']}
//   NcurveRunLine.show(box, {text, machine, shipped: [names], onUse(name), settings}) -> the machine asked or null
(function (global) {
  'use strict';
  const {el} = global.NcurveDom;

  // the comments of the first 12 lines
  const head = (text) => text.split('\n').slice(0, 12).join('\n');

  // the profile named by the first --machine in a comment of the first 12 lines, its folder and
  // .toml taken off; null if none
  function asked(text) {
    const m = /\([^)]*--machine[ =]+(?:\S*\/)?([\w.-]+?)(?:\.toml)?[\s)]/i.exec(head(text));
    return m ? m[1] : null;
  }

  // the --lib, --param and --set of the run line among those comments: the first `(RUN: ...)`, else
  // the first `(... ncurve run ...)`; not a `(RESULT: ... WITHOUT --PARAM 6050=102 ...)` nor a second
  // run line of another case (alarm.nc's `(WITH A DEPTH: ... --set "#100=2" ...)`). Each value as the
  // command line takes it, quotes off.
  function options(text) {
    const out = {lib: [], param: [], set: []};
    const comments = [...head(text).matchAll(/\([^)]*\)/g)].map((m) => m[0]);
    const line = comments.find((c) => /^\(\s*RUN\s*:/i.test(c)) || comments.find((c) => /\bncurve\s+run\b/i.test(c));
    if (line) {
      for (const m of line.matchAll(/--(lib|param|set)(?:\s+|=)("[^"]*"|'[^']*'|[^\s)]+)/gi)) {
        const v = m[2].replace(/^(["'])(.*)\1$/, '$2').trim();
        if (v && !out[m[1].toLowerCase()].includes(v)) out[m[1].toLowerCase()].push(v);
      }
    }
    return out;
  }

  // a folder as written (./macros/, macros) and whether a server folder ({name, path}) is it
  const folder = (f) => f.replace(/^(\.\/)+/, '').replace(/\/+$/, '');
  const isFolder = (asked, l) => folder(l.name) === folder(asked) ||
    (!folder(asked).startsWith('../') && !folder(asked).startsWith('/') && folder(l.path).endsWith('/' + folder(asked))) ||
    folder(l.path) === folder(asked);
  // NUMBER=VALUE's number ("6050", "3401#0", "#100"), to compare a line with the Settings'
  const key = (line) => line.split('=')[0].trim().toUpperCase();

  // what the comments ask that the Settings do not hold: {param, set, lib (served folders' names),
  // unserved (folders the server does not have)}; null if nothing
  function missing(text, settings) {
    const want = options(text), now = settings.request();
    const holds = (list, line) => (list || []).some((l) => key(l) === key(line) && l.replace(/\s/g, '') === line.replace(/\s/g, ''));
    const out = {param: want.param.filter((p) => !holds(now.param, p)), set: want.set.filter((s) => !holds(now.set, s)), lib: [], unserved: []};
    for (const f of want.lib) {
      const l = settings.libs.find((x) => isFolder(f, x));
      if (!l) out.unserved.push(f);
      else if (!now.lib.includes(l.name)) out.lib.push(l.name);
    }
    return out.param.length || out.set.length || out.lib.length || out.unserved.length ? out : null;
  }

  // box: the note's element; machine: the profile chosen ('' the server's); shipped: the names offered
  function show(box, {text, machine, shipped, onUse, settings}) {
    let want = asked(text);
    if (!(want && want !== machine && shipped.includes(want))) want = null;
    const need = settings ? missing(text, settings) : null;
    box.textContent = '';
    box.hidden = !want && !need;
    if (want) {
      const use = el('button', '', `Use ${want}`);
      use.title = `choose the machine ${want} in the header`;
      use.onclick = () => onUse(want);
      box.append(el('span', '', 'This program\u2019s comments ask for '), el('code', '', `--machine ${want}`),
        document.createTextNode(', not the machine chosen. '), use);
    }
    if (!need) return want;
    const words = [...need.lib.map((l) => `--lib ${l}`), ...need.param.map((p) => `--param ${p}`), ...need.set.map((s) => `--set "${s}"`)];
    const unserved = need.unserved.map((f) => `--lib ${f}`);
    if (want) box.append(el('br'));
    box.append(el('span', '', want ? 'They also ask for ' : 'This program\u2019s comments ask for '));
    [...words, ...unserved].forEach((w, k) => box.append(document.createTextNode(k ? ' ' : ''), el('code', '', w)));
    box.append(document.createTextNode(', not in the Settings.'));
    if (words.length) {
      // (named when the folder asked cannot be: the button does not apply that)
      const apply = el('button', 'wb-runline-apply', need.unserved.length ? `Apply ${words.join(' ')}` : 'Apply them');
      apply.title = `put ${words.join(' ')} in the Settings tab (kept in this browser)`;
      apply.onclick = () => settings.use(need);
      box.append(document.createTextNode(' '), apply);
    }
    if (need.unserved.length) {
      const f = need.unserved[0];
      box.append(document.createTextNode(` The folder ${need.unserved.join(', ')} is none of this server\u2019s macro folders: ` +
        'start the server with '), el('code', '', '--lib FOLDER'), document.createTextNode(` (ncurve serve --lib ${f} \u2026) to run it here.`));
    }
    return want;
  }

  global.NcurveRunLine = {asked, options, show};
})(window);
