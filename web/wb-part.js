// The workbench's part: with "Part" ticked, each run asks the server to cut the stock with the
// moves (the program's setup file when the server has one, NAME.setup.toml, else the default box
// and tools) and the part is drawn shaded under the path; at a debugger step the part is cut again
// up to the moves made by then. Its findings come back among the run's diagnostics.
(function (global) {
  'use strict';

  // The setup file of program `name`: NAME.setup.toml.
  const setupName = (name) => name.replace(/\.[^.]*$/, '') + '.setup.toml';

  // The design field's text as POST /api/run takes it: "ellipse a=20 b=12 tol=0.02 wall=edge", or
  // "expr x=20*COS[t] y=12*SIN[t] t=0:360": the curve's name, then NAME=VALUE words (no spaces in a
  // value). Throws an Error saying what is wrong.
  function designRequest(text) {
    const words = text.trim().split(/\s+/).filter(Boolean);
    if (!words.length) return {};
    const curve = {name: words[0], params: {}}, out = {curve};
    for (const w of words.slice(1)) {
      const eq = w.indexOf('=');
      if (eq <= 0) throw new Error(`"${w}": write NAME=VALUE`);
      const key = w.slice(0, eq).replace(/^--/, ''), value = w.slice(eq + 1);
      if (['x', 'y', 'z', 't'].includes(key)) curve[key] = value;
      else if (key === 'wall') out.wall = value;
      else {
        const v = Number(value);
        if (value === '' || !Number.isFinite(v)) throw new Error(`"${w}": ${key} takes a number`);
        if (key === 'tol') out.tol = v;
        else if (key === 'from' || key === 'to') curve[key] = v;
        else curve.params[key] = v;
      }
    }
    return out;
  }

  // checkbox: the "Part" box; design: the field of the design's curve (its walls measured, the part
  // coloured by their errors); setupUrl(name): where the setup of program `name` is, or null;
  // request(): the run request of the program shown; onPart(part, summary): a part to draw (null: none)
  function create({checkbox, design, setupUrl, request, onPart}) {
    const setups = new Map();  // program name -> its setup's text (null: none)
    let stepTimer = 0, stepAbort = null, stepSeq = 0;
    async function setupOf(name) {
      if (setups.has(name)) return setups.get(name);
      const url = setupUrl(name);
      let text = null;
      if (url) {
        const r = await fetch(url);
        if (r.ok) text = await r.text();
      }
      setups.set(name, text);
      return text;
    }
    const api = {
      get on() { return checkbox.checked; },
      // what a run request adds when the part is asked for (a bad design field: an Error)
      async extras(name) {
        if (!checkbox.checked) return {};
        const setup = await setupOf(name);
        const wanted = Object.assign({verify: true}, design ? designRequest(design.value) : {});
        return setup === null ? wanted : Object.assign(wanted, {setup, setup_name: setupName(name)});
      },
      // the part as cut by the first `moves` motions (a debugger's step), a little after the last call
      step(moves) {
        if (!checkbox.checked) return;
        clearTimeout(stepTimer);
        stepTimer = setTimeout(async () => {
          const my = ++stepSeq;
          if (stepAbort) stepAbort.abort();
          stepAbort = new AbortController();
          const base = request();
          // the drawing has at most 400 points a side: a map as fine is enough for a step
          try {
            const body = Object.assign(base, await api.extras(base.name), {moves: false, cut_moves: moves, cells: 400});
            const r = await fetch('/api/run', {method: 'POST', headers: {'Content-Type': 'application/json'},
              signal: stepAbort.signal, body: JSON.stringify(body)});
            const j = await r.json();
            if (my === stepSeq && j.summary) onPart(j.part || null, j.summary, moves);
          } catch (e) { /* a newer step took its place */ }
        }, 120);
      },
      forget() { setups.clear(); },
    };
    return api;
  }

  global.NcurvePart = {create, setupName, designRequest};
})(window);
