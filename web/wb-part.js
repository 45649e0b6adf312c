// The workbench's part: with "Part" ticked, each run asks the server to cut the stock with the
// moves (the program's setup file when the server has one, NAME.setup.toml, else the default box
// and tools) and the part is drawn shaded under the path; at a debugger step the part is cut again
// up to the moves made by then. Its findings come back among the run's diagnostics.
(function (global) {
  'use strict';

  // The setup file of program `name`: NAME.setup.toml.
  const setupName = (name) => name.replace(/\.[^.]*$/, '') + '.setup.toml';

  // checkbox: the "Part" box; setupUrl(name): where the setup of program `name` is, or null;
  // request(): the run request of the program shown; onPart(part, summary): a part to draw (null: none)
  function create({checkbox, setupUrl, request, onPart}) {
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
      // what a run request adds when the part is asked for
      async extras(name) {
        if (!checkbox.checked) return {};
        const setup = await setupOf(name);
        return setup === null ? {verify: true} : {verify: true, setup, setup_name: setupName(name)};
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
          const body = Object.assign(base, await api.extras(base.name), {moves: false, cut_moves: moves, cells: 400});
          try {
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

  global.NcurvePart = {create, setupName};
})(window);
