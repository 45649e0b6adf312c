// The machine a program's opening comments ask for: a `--machine NAME` as the examples' RUN lines
// write it (`(RUN: ./build/ncurve run examples/4-axis.nc --machine profiles/fanuc-4axis-helicoid.toml)`).
// When it is a shipped profile and not the one chosen, a note under the editor says so, with a button
// that chooses it: picking 4-axis.nc from the menu on a 3-axis mill tells why it alarms (PS0009).
//   NcurveRunLine.asked(text) -> 'fanuc-4axis-helicoid' or null
//   NcurveRunLine.show(box, {text, machine, shipped: [names], onUse(name)})
(function (global) {
  'use strict';
  const {el} = global.NcurveDom;

  // the profile named by the first --machine in a comment of the first 12 lines, its folder and
  // .toml taken off; null if none
  function asked(text) {
    const head = text.split('\n').slice(0, 12).join('\n');
    const m = /\([^)]*--machine[ =]+(?:\S*\/)?([\w.-]+?)(?:\.toml)?[\s)]/i.exec(head);
    return m ? m[1] : null;
  }

  // box: the note's element; machine: the profile chosen ('' the server's); shipped: the names offered
  function show(box, {text, machine, shipped, onUse}) {
    const want = asked(text);
    box.textContent = '';
    box.hidden = !(want && want !== machine && shipped.includes(want));
    if (box.hidden) return null;
    const use = el('button', '', `Use ${want}`);
    use.title = `choose the machine ${want} in the header`;
    use.onclick = () => onUse(want);
    box.append(el('span', '', 'This program\u2019s comments ask for '), el('code', '', `--machine ${want}`),
      document.createTextNode(', not the machine chosen. '), use);
    return want;
  }

  global.NcurveRunLine = {asked, show};
})(window);
