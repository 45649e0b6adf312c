// The workbench's files: the program saved as a download named as the program (Save, Ctrl+S), a
// file of this computer opened (Open, or dropped onto the editor), a new empty program, a program
// pasted over the whole editor named untitled.nc; and the editor's text, the program's name and the
// machine kept in this browser (localStorage) across a reload. A program of this browser (new,
// opened, pasted, restored) has its own entry in the Program menu, and its name is the one its
// diagnostics give.
//   const f = NcurveFiles.create({editor, menu, name(), load(text, name), onSave(name)});
//   f.local(name, kind, text?), f.store(), f.restored(), f.choose() on the menu's entry
(function (global) {
  'use strict';
  const $ = (id) => document.getElementById(id);
  const KEY = 'ncurve-workbench-program';
  const LOCAL = '\u0000local';
  const UNTITLED = 'untitled.nc';

  // editor: NcurveEditor; menu: the Program <select>; name(): the program's name now;
  // load(text, name): the program shown, named so, run; machine(): {value, file: {name, text}}
  function create({editor, menu, name, load, rename, machine}) {
    let local = null;  // {name, kind, text}: the program of this browser
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
      return local ? load(local.text, local.name) : Promise.resolve();
    }
    // a restored program: its server file's entry when it was one (its text as edited), else its own
    function restore(saved, serverNames) {
      if (!saved.local && serverNames.includes(saved.menu)) {
        menu.value = saved.menu;
        return load(saved.text, saved.name);
      }
      return useLocal(saved.name || UNTITLED, saved.local || 'restored', saved.text);
    }
    return {useLocal, store, storeSoon, restored, restore, choose, save, LOCAL, UNTITLED,
      get local() { return local; }};
  }

  global.NcurveFiles = {create};
})(window);
