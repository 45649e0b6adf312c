// The workbench's files: the program saved as a download named as the program (Save, Ctrl+S), a
// file of this computer opened (Open, or dropped onto the editor), a new empty program, a program
// pasted over the whole editor named untitled.nc; and the editor's text, the program's name and the
// machine kept in this browser (localStorage) across a reload. A program of this browser (new,
// opened, pasted, restored) has its own entry in the Program menu, and its name is the one its
// diagnostics give. A server file's edits are kept per file (in memory and in this browser) until
// its text is the file's again or Revert reads the file anew: choosing it again brings them back,
// and its menu entry and the page's title say it is edited. Save downloads a copy and leaves the
// server's file as it is, so the mark stays.
//   const f = NcurveFiles.create({editor, menu, name(), load(text, name), rename(n), machine()});
//   f.local(name, kind, text?), f.store(), f.restored(), f.choose() on the menu's entry,
//   f.opened(file, disk) -> the text to show, f.noteEdit() on each edit, f.revert()
(function (global) {
  'use strict';
  const $ = (id) => document.getElementById(id);
  const KEY = 'ncurve-workbench-program';
  const EDITS = 'ncurve-workbench-edits';  // {file: text} of the server's files edited
  const same = (a, b) => a.replace(/\r\n?/g, '\n') === b.replace(/\r\n?/g, '\n');  // a textarea's line ends are \n
  const LOCAL = '\u0000local';
  const UNTITLED = 'untitled.nc';

  // editor: NcurveEditor; menu: the Program <select>; name(): the program's name now;
  // load(text, name): the program shown, named so, run; machine(): {value, file: {name, text}}
  function create({editor, menu, name, load, rename, machine}) {
    let local = null;  // {name, kind, text}: the program of this browser
    let edits = {};
    try { edits = JSON.parse(localStorage.getItem(EDITS) || '{}') || {}; } catch (e) { edits = {}; }
    const disk = {};  // file -> its text as last read from the server
    let current = null;  // the server file in the editor, while its entry is the menu's choice
    const serverFile = () => (current !== null && menu.value === current ? current : null);
    function entry(label) {
      let o = [...menu.options].find((x) => x.value === LOCAL);
      if (!o) { o = new Option('', LOCAL); menu.add(o, 0); }
      o.text = label;
      menu.value = LOCAL;
    }
    // a program of this browser: named `n`, its `kind` (new, opened, pasted, restored) in the menu;
    // with text: shown in the editor and run, else (a paste to come) the editor's
    function useLocal(n, kind, text) {
      local = {name: n, kind, text: text === undefined ? editor.text : text};
      entry(`${n} (${kind})`);
      if (text === undefined) rename(n);
      const done = text === undefined ? Promise.resolve() : load(text, n);
      store();
      return done;
    }

    // ---- save: a download of the editor's text, named as the program ----
    function save() {
      const n = name() || UNTITLED, url = URL.createObjectURL(new Blob([editor.text], {type: 'text/plain'}));
      const a = document.createElement('a');
      a.href = url;
      a.download = n;
      a.hidden = true;
      document.body.append(a);
      a.click();
      a.remove();
      setTimeout(() => URL.revokeObjectURL(url), 10000);
      global.ncurveWorkbench.saved = {name: n, bytes: editor.text.length};
    }
    $('save').onclick = save;
    // Ctrl+S (Cmd+S): the program saved, not the page
    document.addEventListener('keydown', (e) => {
      if (!(e.ctrlKey || e.metaKey) || e.altKey || e.key.toLowerCase() !== 's') return;
      e.preventDefault();
      save();
    }, true);

    // ---- open: a file of this computer, picked or dropped onto the editor ----
    async function openFile(f) {
      if (!f) return;
      useLocal(f.name, 'opened', await f.text());
    }
    $('open').onclick = () => { $('open-file').value = ''; $('open-file').click(); };
    $('open-file').onchange = () => openFile($('open-file').files[0]);
    const hasFiles = (e) => e.dataTransfer && [...e.dataTransfer.types].includes('Files');
    const zone = editor.root.parentElement;
    zone.addEventListener('dragover', (e) => {
      if (!hasFiles(e)) return;
      e.preventDefault();
      e.dataTransfer.dropEffect = 'copy';
      zone.classList.add('wb-drop');
    });
    zone.addEventListener('dragleave', () => zone.classList.remove('wb-drop'));
    zone.addEventListener('drop', (e) => {
      zone.classList.remove('wb-drop');
      if (!hasFiles(e) || !e.dataTransfer.files.length) return;
      e.preventDefault();
      e.stopPropagation();
      openFile(e.dataTransfer.files[0]);
    }, true);
    // a file dropped elsewhere on the page is not opened by the browser in place of the workbench
    for (const ev of ['dragover', 'drop']) window.addEventListener(ev, (e) => { if (hasFiles(e)) e.preventDefault(); });

    // ---- new, pasted ----
    $('new').onclick = () => useLocal(UNTITLED, 'new', '');
    // a paste over the whole text (or into an empty editor) is a new program, not an edit of the last
    editor.input.addEventListener('paste', () => {
      const t = editor.input;
      if ((t.selectionStart === 0 && t.selectionEnd === t.value.length) || !/\S/.test(t.value)) useLocal(UNTITLED, 'pasted');
    });

    // ---- kept in this browser ----
    let timer = 0;
    function store() {
      clearTimeout(timer);
      timer = 0;
      if (local && menu.value === LOCAL) local.text = editor.text;
      noteEdit();
      try { localStorage.setItem(EDITS, JSON.stringify(edits)); } catch (e) { /* over the quota: kept for this page */ }
      const m = machine();
      const state = {text: editor.text, name: name(), local: menu.value === LOCAL ? local && local.kind : null,
        menu: menu.value === LOCAL ? null : menu.value, machine: m.value, machineFile: m.file || null};
      try {
        localStorage.setItem(KEY, JSON.stringify(state));
        global.ncurveWorkbench.storeError = null;
      } catch (e) {  // over the browser's quota (a few MB): the program is not kept
        global.ncurveWorkbench.storeError = String(e);
      }
    }
    const storeSoon = () => { clearTimeout(timer); timer = setTimeout(store, 250); };
    window.addEventListener('pagehide', store);
    function restored() {
      try { return JSON.parse(localStorage.getItem(KEY) || 'null'); } catch (e) { return null; }
    }
    // the menu's entry of this browser's program chosen again: its text back
    function choose() {
      const done = local ? load(local.text, local.name) : Promise.resolve();
      mark();
      return done;
    }
    // a restored program: its server file's entry when it was one (its text as edited), else its own
    function restore(saved, serverNames, open) {
      if (!saved.local && serverNames.includes(saved.menu)) {
        // its edits are kept per file; a text kept before they were is taken as its edit
        if (edits[saved.menu] === undefined) edits[saved.menu] = saved.text;
        menu.value = saved.menu;
        return open(saved.menu);
      }
      return useLocal(saved.name || UNTITLED, saved.local || 'restored', saved.text);
    }
    // ---- the program opened first ----
    // the first program given, unless its opening comments ask for another machine than `machine`
    // (a `--machine NAME` as the examples' RUN lines write it): then the machine's shipped example
    // when the server has it (the program the README tours), else the next that asks for none
    async function first(programs, exampleName, machine) {
      const head = async (f) => {
        const r = await fetch('/api/files/' + encodeURIComponent(f));
        return r.ok ? (await r.text()).split('\n').slice(0, 12).join('\n') : '';
      };
      const other = (text) => {
        const m = /\(.*--machine[ =]+(?:\S*\/)?([\w.-]+?)(?:\.toml)?[\s)]/i.exec(text);
        return m && m[1] !== machine;
      };
      if (!programs.length || !other(await head(programs[0]))) return programs[0] || '';
      if (programs.includes(exampleName)) return exampleName;
      for (const f of programs.slice(1)) if (!other(await head(f))) return f;
      return programs[0];
    }

    // ---- a server file's edits: kept per file, marked, reverted ----
    // a server file read from disk: its edits if it has some (dropped when the file now holds them)
    function opened(file, text) {
      disk[file] = text;
      current = file;
      const kept = edits[file];
      if (kept !== undefined && same(kept, text)) delete edits[file];
      mark();
      return edits[file] !== undefined ? edits[file] : text;
    }
    // the editor's text against its file's on disk: an edit kept, or none when they are the same again
    function noteEdit() {
      const f = serverFile();
      if (f !== null && disk[f] !== undefined) {
        if (same(editor.text, disk[f])) delete edits[f];
        else edits[f] = editor.text;
      }
      mark();
    }
    // the menu's entries of the files edited, the Revert button and the page's title
    function mark() {
      for (const o of menu.options) {
        if (o.value === LOCAL || o.value.startsWith('\u0000') || !o.value) continue;
        o.text = o.value + (edits[o.value] !== undefined ? ' (edited)' : '');
      }
      const f = serverFile(), edited = f !== null && edits[f] !== undefined;
      $('revert').disabled = !edited;
      $('revert').title = edited ? `read ${f} again from the server, the edits dropped` : 'the program is as its file on the server';
      document.title = `${edited ? '\u25cf ' : ''}${name() || UNTITLED}${edited ? ' (edited)' : ''} \u00b7 ncurve workbench`;
      global.ncurveWorkbench.edited = Object.keys(edits);
    }
    // Revert: the file read again from the server, its edits dropped (asked first)
    async function revert() {
      const f = serverFile();
      if (f === null || edits[f] === undefined) return;
      if (!global.confirm(`Revert ${f} to the file on the server? The edits made here are lost.`)) return;
      const r = await fetch('/api/files/' + encodeURIComponent(f));
      if (!r.ok) { global.ncurveWorkbench.error = `revert: ${r.status}`; return; }
      delete edits[f];
      const text = await r.text();
      await load(opened(f, text), f);
      store();
    }
    $('revert').onclick = revert;

    return {useLocal, store, storeSoon, restored, restore, choose, save, first, opened, noteEdit, mark, revert, LOCAL, UNTITLED,
      get local() { return local; }};
  }

  global.NcurveFiles = {create};
})(window);
