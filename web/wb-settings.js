// The workbench's Settings tab: the command line's run options, sent with every run and analyze
// request (POST /api/run, /api/analyze) as the API takes them: parameters ("param", as --param, one
// a line), variable presets ("set", as --set), the macro folders among the server's ("lib", as
// --lib; GET /api/libs lists them), the most steps ("max_steps") and the tool offsets edited over
// the profile's ("tool_offsets"). Kept in this browser (localStorage) across a reload; what is in
// force is named in the header; a refused one's message (the server's 400, in the command line's
// words) is shown beside its field. Max steps is checked here first, as `run --max-steps` checks it
// ("--max-steps: 'abc' is not a number ..."): a bad one is refused beside its field before any run.
//   const s = NcurveSettings.create({note, onChange}); s.setLibs(libs); s.showProfile(profile, key);
//   Object.assign(request, s.request(key)); s.refused(message) -> the message shown beside a field
//   ('' none); s.refused('') before a request: the page's own refusal, else the fields cleared
//   s.use({param: [...], set: [...], lib: [names]}): the lines put in the parameters and variables
//   (one of the same number replaced), the folders ticked, and a run (a program's RUN comment,
//   wb-runline.js); s.libs: the server's folders (GET /api/libs)
(function (global) {
  'use strict';
  const {el, fmt} = global.NcurveDom;
  const $ = (id) => document.getElementById(id);
  const KEY = 'ncurve-workbench-settings';
  // the offset fields of a profile, in the words of its [tool_offsets], with the page's labels
  const FIELDS = {
    A: [['length', 'H and D, mm']],
    B: [['length', 'H and D, mm'], ['length_wear', 'wear, mm']],
    C: [['length', 'H length, mm'], ['length_wear', 'H wear, mm'], ['radius', 'D radius, mm'], ['radius_wear', 'D wear, mm']],
    lathe: [['x', 'X, mm'], ['z', 'Z, mm'], ['r', 'nose R, mm'], ['tip', 'tip'], ['x_wear', 'X wear'], ['z_wear', 'Z wear'],
      ['r_wear', 'R wear']],
  };

  // a line as the command line's value: "--param 6050=102", "--set "#100=2"" and quotes taken off
  const value = (line, option) => line.trim().replace(new RegExp(`^--${option}(\\s+|=)`), '').replace(/^(["'])(.*)\1$/, '$2').trim();
  const lines = (text, option) => text.split('\n').map((l) => value(l, option)).filter((l) => l && !l.startsWith('//'));

  function create({note, onChange}) {
    let saved = {};
    try { saved = JSON.parse(localStorage.getItem(KEY) || '{}') || {}; } catch (e) { saved = {}; }
    // lib: null until chosen (all the server's folders); offsets: {machine key: {N: {field: value}}}
    const state = {param: saved.param || '', set: saved.set || '', steps: saved.steps || '',
      lib: Array.isArray(saved.lib) ? saved.lib : null, offsets: saved.offsets || {}};
    let libs = [], profile = {}, key = '', shownProfile = '', timer = 0;
    $('set-param').value = state.param;
    $('set-vars').value = state.set;
    $('set-steps').value = state.steps;
    const store = () => {
      try { localStorage.setItem(KEY, JSON.stringify(state)); } catch (e) { /* full: kept for this page only */ }
    };
    const changed = (now) => {
      store();
      showNote();
      clearTimeout(timer);
      timer = now ? 0 : setTimeout(onChange, 400);
      if (now) onChange();
    };
    const field = (id, prop) => {
      $(id).addEventListener('input', () => { state[prop] = $(id).value; changed(false); });
      $(id).addEventListener('change', () => { state[prop] = $(id).value; clearTimeout(timer); timer = 0; changed(true); });
    };
    field('set-param', 'param');
    field('set-vars', 'set');
    field('set-steps', 'steps');

    const chosenLibs = () => (state.lib === null ? libs.map((l) => l.name) : state.lib.filter((n) => libs.some((l) => l.name === n)));
    function setLibs(list) {
      libs = list;
      const box = $('set-libs');
      box.textContent = '';
      if (!libs.length) box.append(el('span', 'wb-hint', 'none: the server was started without --lib (ncurve serve --lib DIR)'));
      for (const l of libs) {
        const label = el('label', 'wb-set-lib');
        const c = el('input');
        c.type = 'checkbox';
        c.value = l.name;
        c.checked = chosenLibs().includes(l.name);
        c.onchange = () => {
          state.lib = [...box.querySelectorAll('input:checked')].map((x) => x.value);
          changed(true);
        };
        const n = l.program_count;
        label.title = `${l.path}: ${l.error || (l.programs.join(' ') + (n > l.programs.length ? ' …' : ''))}`;
        label.append(c, document.createTextNode(` ${l.name} `), el('span', 'wb-hint', l.error ? `(${l.error})` : `(${n} program${n === 1 ? '' : 's'})`));
        box.append(label);
      }
      showNote();
    }

    // ---- the tool offsets: the profile's, and those edited over it (per machine) ----
    const kind = () => (profile.lathe ? 'lathe' : FIELDS[profile.offset_memory] ? profile.offset_memory : 'A');
    const edits = () => state.offsets[key] || {};
    const base = (n, f) => {
      const o = (profile.tool_offsets || {})[n];
      return o === undefined ? 0 : typeof o === 'number' ? o : o[f] === undefined ? 0 : o[f];
    };
    function showOffsets() {
      const table = $('set-offsets'), fields = FIELDS[kind()], ed = edits();
      table.textContent = '';
      $('set-offsets-doc').textContent = profile.lathe ? 'the lathe\'s offset sets (T0101: set 1), X a diameter'
        : `offset memory ${kind()}: ${kind() === 'C' ? 'H and D apart' : 'one value for H and D'} (G43 H, G41 D)`;
      const head = el('tr');
      head.append(el('th', '', 'No.'), ...fields.map(([, label]) => el('th', '', label)), el('th'));
      table.append(head);
      const numbers = [...new Set([...Object.keys(profile.tool_offsets || {}), ...Object.keys(ed)])].sort((a, b) => a - b);
      if (!numbers.length) {
        const tr = el('tr'), td = el('td', 'wb-hint', 'the profile sets no offset: add one by its number');
        td.colSpan = fields.length + 2;
        tr.append(td);
        table.append(tr);
      }
      for (const n of numbers) {
        const tr = el('tr');
        tr.dataset.offset = n;
        tr.append(el('td', '', n));
        for (const [f, label] of fields) {
          const td = el('td'), input = el('input');
          const own = ed[n] && ed[n][f] !== undefined;
          input.size = 7;
          input.dataset.field = f;
          input.value = own ? ed[n][f] : fmt(base(n, f), 4);
          input.title = `offset ${n} ${label}; the profile's: ${fmt(base(n, f), 4)}`;
          if (own) td.className = 'changed';
          input.onchange = () => setOffset(n, f, input.value);
          td.append(input);
          tr.append(td);
        }
        const td = el('td');
        if (ed[n]) {
          const undo = el('button', '', 'profile\'s');
          undo.title = `offset ${n} as the profile gives it`;
          undo.onclick = () => { delete state.offsets[key][n]; showOffsets(); changed(true); };
          td.append(undo);
        }
        tr.append(td);
        table.append(tr);
      }
    }
    function setOffset(n, f, text) {
      const t = text.trim(), ed = state.offsets[key] = state.offsets[key] || {};
      ed[n] = ed[n] || {};
      if (t === '' || Number(t) === base(n, f)) delete ed[n][f];
      else ed[n][f] = t;
      if (!Object.keys(ed[n]).length) delete ed[n];
      showOffsets();
      changed(true);
    }
    $('set-offset-add').onclick = () => {
      const n = $('set-offset-new').value.trim();
      const most = profile.lathe ? 64 : 999;
      if (!/^\d+$/.test(n) || +n < 1 || +n > most) {
        $('set-offsets-why').textContent = `"${n}": an offset number is 1 .. ${most}`;
        return;
      }
      $('set-offsets-why').textContent = '';
      const ed = state.offsets[key] = state.offsets[key] || {}, f = FIELDS[kind()][0][0];
      if (!ed[+n] && !(profile.tool_offsets || {})[+n]) ed[+n] = {[f]: '0'};
      $('set-offset-new').value = '';
      showOffsets();
      const input = $('set-offsets').querySelector(`tr[data-offset="${+n}"] input`);
      if (input) input.focus();
      changed(true);
    };
    $('set-offsets-reset').onclick = () => { delete state.offsets[key]; showOffsets(); changed(true); };

    // ---- what is sent, what is in force, what was refused ----
    const num = (t) => (/^\s*[-+]?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?\s*$/i.test(t) ? Number(t) : t);
    // Max steps as the command line checks --max-steps (a whole number from 1 to 1e+15, in its
    // words); '' when it is one or empty
    function stepsWhy() {
      const t = state.steps.trim();
      if (!t) return '';
      if (!/^\+?(-?(\d+\.?\d*|\.\d+)(e[-+]?\d+)?|-?inf(inity)?|-?nan)$/i.test(t))
        return `--max-steps: '${t}' is not a number (expected a whole number from 1 to 1e+15)`;
      const v = Number(t.replace(/^\+/, '').replace(/inf(inity)?$/i, 'Infinity'));
      return Number.isInteger(v) && v >= 1 && v <= 1e15 ? '' : `--max-steps: must be a whole number from 1 to 1e+15, got ${t}`;
    }
    function offsetsRequest() {
      const ed = edits(), out = {};
      for (const n of Object.keys(ed)) {
        out[n] = {};
        for (const f of Object.keys(ed[n])) out[n][f] = num(ed[n][f]);
      }
      return Object.keys(out).length ? out : undefined;
    }
    function request(extraParams) {
      const param = lines(state.param, 'param').concat(extraParams || []), set = lines(state.set, 'set');
      return {param: param.length ? param : undefined, set: set.length ? set : undefined, lib: chosenLibs(),
        max_steps: state.steps.trim() ? num(state.steps) : undefined, tool_offsets: offsetsRequest()};
    }
    // an offset's edited fields as the note says them: offset memory A and B hold one value an
    // offset number, used as H's length and as D's radius alike, and the note says so
    function offsetWords(fields) {
      const words = Object.keys(fields).map((f) => `${f} ${fields[f]}`).join(' ');
      if (profile.lathe || kind() === 'C') return words;
      const one = fields.length === undefined ? '' : `${fields.length} (H length and D radius)`;
      const wear = fields.length_wear === undefined ? '' : `wear ${fields.length_wear}`;
      return [one, wear].filter(Boolean).join(', ');
    }
    // the command line's options the page runs with (what a plain `ncurve run` does not)
    function inForce() {
      const words = [];
      for (const p of lines(state.param, 'param')) words.push(`--param ${p}`);
      for (const s of lines(state.set, 'set')) words.push(`--set "${s}"`);
      for (const l of chosenLibs()) words.push(`--lib ${l}`);
      if (state.steps.trim()) words.push(`--max-steps ${state.steps.trim()}`);
      const ed = edits(), o = Object.keys(ed).map((n) => `${profile.lathe ? '' : 'No.'}${n} ${offsetWords(ed[n])}`);
      if (o.length) words.push(`tool offsets: ${o.join(', ')}`);
      return words;
    }
    function showNote() {
      const words = inForce();
      note.textContent = words.length ? `with ${words.join(' ')}` : '';
      note.title = words.length ? `the Settings in force (click to see them): ${words.join(' ')}` : '';
      note.hidden = !words.length;
      const tab = document.querySelector('.wb-tabs button[data-tab="settings"]');
      if (tab) tab.textContent = words.length ? `Settings (${words.length})` : 'Settings';
    }
    // the server's 400 beside the field it is about, returned; null: none refused
    const WHY = [['--param', 'set-param-why'], ['--set', 'set-vars-why'], ['--max-steps', 'set-steps-why'], ['"param"', 'set-param-why'], ['"set"', 'set-vars-why'],
      ['"lib"', 'set-lib-why'], ['"max_steps"', 'set-steps-why'], ['"tool_offsets"', 'set-offsets-why']];
    // (a Max steps the page refuses is the refusal, whatever else the server said)
    function refused(message) {
      for (const [, id] of WHY) $(id).textContent = '';
      for (const id of ['set-param', 'set-vars', 'set-steps']) $(id).removeAttribute('aria-invalid');
      message = stepsWhy() || message;
      if (!message) return '';
      const hit = WHY.find(([prefix]) => message.startsWith(prefix));
      if (!hit) return '';
      $(hit[1]).textContent = message;
      const input = {'set-param-why': 'set-param', 'set-vars-why': 'set-vars', 'set-steps-why': 'set-steps'}[hit[1]];
      if (input) $(input).setAttribute('aria-invalid', 'true');
      return message;
    }
    // lines, folders put in the Settings (a line of the same NUMBER= replaced), then a run
    function use({param, set, lib}) {
      const merge = (text, option, add) => {
        const key = (l) => value(l, option).split('=')[0].trim().toUpperCase();
        const keep = text.split('\n').filter((l) => l.trim() && !add.some((a) => key(a) === key(l)));
        return keep.concat(add).join('\n');
      };
      if (param && param.length) $('set-param').value = state.param = merge(state.param, 'param', param);
      if (set && set.length) $('set-vars').value = state.set = merge(state.set, 'set', set);
      if (lib && lib.length && state.lib !== null) state.lib = [...new Set(state.lib.concat(lib))];
      setLibs(libs);
      changed(true);
    }
    function showProfile(p, machineKey) {
      const shown = machineKey + '\u0000' + JSON.stringify([p.lathe, p.offset_memory, p.tool_offsets]);
      profile = p || {};
      key = machineKey;
      if (shown === shownProfile) return;
      shownProfile = shown;
      showOffsets();
      showNote();
    }
    showNote();
    return {setLibs, showProfile, request, refused, inForce, use, get state() { return state; }, get libs() { return libs; }};
  }

  global.NcurveSettings = {create, lines};
})(window);
