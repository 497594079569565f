// cagd serve: the teacher's page. A problem's JSON in a text box: its key and statement
// (/api/teacher/solve), its interactive figure (a form posted into an iframe), its LaTeX
// key and statement sheet (a form posted to /teacher/download), and the problem as the
// students will see it (/api/teacher/preview, drawn by common.js as on the student's page).
'use strict';

(async () => {
  // The example the text box starts with: a Bézier Coons patch (data, not words).
  const EXAMPLE = {
    title: 'Bézier Coons patch of bidegree (3, 2)',
    es: { title: 'Superficie de Coons de Bézier de bigrado (3, 2)' },
    op: 'coons',
    c1: { bezier: [[0, 0, 0], ['1/2', 0, 2], [1, 0, 3], [2, 0, 0]] },
    c2: { bezier: [[0, 3, 0], ['1/2', 3, 3], [1, 3, 1], [2, 4, 0]] },
    d1: { bezier: [[0, 0, 0], [0, 1, 3], [0, 3, 0]] },
    d2: { bezier: [[2, 0, 0], [2, 1, 2], [2, 4, 0]] },
  };
  const $ = (id) => document.getElementById(id);
  const text = $('problem');
  const status = $('status');
  const failure = Cagd.el('div', 'message error');
  failure.id = 'failure';
  failure.setAttribute('role', 'alert');
  failure.hidden = true;
  status.after(failure);
  // JSON with each innermost array (a point) on one line.
  function pretty(v) {
    return JSON.stringify(v, null, 2).replace(/\[\s+([^[\]{}]*?)\s+\]/g,
      (m, inner) => '[' + inner.split(/,\s*/).join(', ') + ']');
  }
  if (!text.value) text.value = pretty(EXAMPLE);

  // The words: the served set's (GET /api/set), else a preview's of the example.
  const q = Cagd.lang ? '?lang=' + encodeURIComponent(Cagd.lang) : '';
  let first = null;
  try {
    first = await Cagd.api('/api/set' + q);
  } catch (err) {
    try {
      first = await Cagd.api('/api/teacher/preview', { set: [EXAMPLE], lang: Cagd.lang || undefined });
    } catch (err2) {
      Cagd.showError(failure, err2);
    }
  }
  if (first && first.words) Cagd.setWords(first.words);
  Cagd.setLang((first && first.lang) || Cagd.lang);
  const w = Cagd.word;

  document.title = w('teacher_title');
  const top = $('top');
  top.textContent = '';
  top.appendChild(Cagd.languageSwitch());
  top.appendChild(Cagd.el('h1', null, w('teacher_title')));
  $('problem-json-label').textContent = w('problem_json');
  $('solve').textContent = w('solve');
  $('preview').textContent = w('preview');
  $('download-key').textContent = w('download_key');
  $('download-sheet').textContent = w('download_sheet');
  $('errors-heading').textContent = w('errors');
  $('statement-heading').textContent = w('statement');
  $('figure-heading').textContent = w('interactive_figure');
  $('key-heading').textContent = w('key');
  $('figure').title = w('interactive_figure');
  $('preview-note').textContent = w('preview_note');

  function clearMessages() {
    failure.hidden = true;
    failure.textContent = '';
    $('errors').hidden = true;
    $('error-list').textContent = '';
  }

  // The text box's JSON, or null (the reason shown as an error).
  function parsed() {
    try {
      return JSON.parse(text.value);
    } catch (e) {
      showErrors([{ path: '', message: w('not_json') + ' ' + e.message }]);
      return null;
    }
  }

  function showErrors(errors) {
    const list = $('error-list');
    list.textContent = '';
    for (const e of errors) {
      const li = Cagd.el('li', 'error-item');
      const path = String(e.path || '');
      li.setAttribute('data-path', path);
      if (path) {
        const b = Cagd.el('button', 'path', path);
        b.type = 'button';
        b.addEventListener('click', () => focusPath(path));
        li.appendChild(b);
      }
      li.appendChild(Cagd.el('span', 'message-text', String(e.message || '')));
      list.appendChild(li);
    }
    $('errors').hidden = false;
  }

  // The place in the text of a path such as `c1.bezier[2]` (found by reading the JSON text
  // key by key; -1 when it is not found).
  function findPath(src, path) {
    const steps = [];
    for (const m of path.matchAll(/([^.[\]]+)|\[(\d+)\]/g)) {
      if (m[2] !== undefined) steps.push(Number(m[2]));
      else steps.push(m[1]);
    }
    let pos = 0;
    for (const s of steps) {
      if (typeof s === 'string') {
        const re = new RegExp('"' + s.replace(/[.*+?^${}()|[\]\\]/g, '\\$&') + '"\\s*:', 'g');
        re.lastIndex = pos;
        const m = re.exec(src);
        if (!m) return pos;
        pos = m.index;
        pos = src.indexOf(':', pos) + 1;
      } else {
        const open = src.indexOf('[', pos);
        if (open < 0) return pos;
        let depth = 0;
        let count = 0;
        let inString = false;
        let i = open + 1;
        for (; i < src.length && count < s; i++) {
          const c = src[i];
          if (inString) {
            if (c === '\\') i++;
            else if (c === '"') inString = false;
          } else if (c === '"') inString = true;
          else if (c === '[' || c === '{') depth++;
          else if (c === ']' || c === '}') {
            if (depth === 0) return open;
            depth--;
          } else if (c === ',' && depth === 0) count++;
        }
        pos = i;
        while (pos < src.length && /\s/.test(src[pos])) pos++;
      }
    }
    return pos;
  }

  function focusPath(path) {
    const pos = findPath(text.value, path);
    if (pos < 0) return;
    const lineStart = text.value.lastIndexOf('\n', pos - 1) + 1;
    let lineEnd = text.value.indexOf('\n', pos);
    if (lineEnd < 0) lineEnd = text.value.length;
    text.focus();
    text.setSelectionRange(lineStart, lineEnd);
    const line = text.value.slice(0, lineStart).split('\n').length - 1;
    const lh = parseFloat(getComputedStyle(text).lineHeight) || 18;
    text.scrollTop = Math.max(0, line * lh - text.clientHeight / 3);
  }

  async function busy(button, work) {
    clearMessages();
    button.disabled = true;
    status.textContent = w('loading');
    try {
      await work();
    } catch (err) {
      Cagd.showError(failure, err);
    } finally {
      button.disabled = false;
      status.textContent = '';
    }
  }

  $('solve').addEventListener('click', () => busy($('solve'), async () => {
    const problem = parsed();
    if (problem === null) return;
    const data = await Cagd.api('/api/teacher/solve', { problem, lang: Cagd.lang });
    if (data.ok === false) {
      $('solved').hidden = true;
      showErrors(Array.isArray(data.errors) ? data.errors : []);
      return;
    }
    Cagd.setHtml($('statement'), data.statement_html);
    Cagd.setHtml($('key'), data.key_html);
    $('solved').hidden = false;
    const form = $('figure-form');
    form.elements.problem.value = text.value;
    form.elements.lang.value = Cagd.lang;
    form.elements.token.value = Cagd.token;
    form.submit();
  }));

  $('preview').addEventListener('click', () => busy($('preview'), async () => {
    const v = parsed();
    if (v === null) return;
    const set = Array.isArray(v) || (v && typeof v === 'object' && Array.isArray(v.problems)) ? v : [v];
    const data = await Cagd.api('/api/teacher/preview', { set, lang: Cagd.lang });
    if (data.ok === false) {
      $('preview-area').hidden = true;
      showErrors(Array.isArray(data.errors) ? data.errors : []);
      return;
    }
    const box = $('preview-set');
    box.textContent = '';
    if (data.title) box.appendChild(Cagd.el('h2', 'set-title', data.title));
    const problems = Cagd.el('div', 'problems');
    box.appendChild(problems);
    Cagd.drawSet(problems, data, { interactive: false });
    $('preview-area').hidden = false;
    $('preview-area').scrollIntoView({ block: 'start' });
  }));

  function download(what) {
    clearMessages();
    if (parsed() === null) return;
    const form = $('download-form');
    form.elements.problem.value = text.value;
    form.elements.what.value = what;
    form.elements.lang.value = Cagd.lang;
    form.elements.token.value = Cagd.token;
    form.submit();
  }
  $('download-key').addEventListener('click', () => download('key'));
  $('download-sheet').addEventListener('click', () => download('sheet'));
})();
