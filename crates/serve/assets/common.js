// cagd serve: what the student's page and the teacher's page share (the HTTP calls, the
// language switch, KaTeX, and the drawing of a problem set with its answer cells).
// Text from the server goes in with textContent; only the API's `*_html` fields go in as
// HTML (the server escapes them), and mathematics only through KaTeX.
'use strict';

const Cagd = (() => {
  const params = new URLSearchParams(window.location.search);
  const token = params.get('token') || '';
  const urlLang = params.get('lang') === 'en' || params.get('lang') === 'es' ? params.get('lang') : '';

  // Said only when the words themselves could not be loaded.
  const FALLBACK = {
    busy: 'The server is busy; try again in a moment. / El servidor está ocupado; vuelva a intentarlo en un momento.',
    failed: 'The request failed: / La petición ha fallado:',
    unreachable: 'The server cannot be reached. / No se puede conectar con el servidor.',
  };

  let words = {};
  function setWords(w) { words = w || {}; }
  function word(id) {
    return Object.prototype.hasOwnProperty.call(words, id) ? words[id] : (FALLBACK[id] || id);
  }

  // An element with a class and text (never HTML).
  function el(tag, cls, text) {
    const e = document.createElement(tag);
    if (cls) e.className = cls;
    if (text !== undefined && text !== null) e.textContent = text;
    return e;
  }

  class ApiError extends Error {
    constructor(kind, detail, status) {
      super(kind);
      this.kind = kind; // 'busy' | 'failed' | 'unreachable'
      this.detail = detail || '';
      this.status = status || 0;
    }
  }

  // A JSON call; a POST when body is given. Throws ApiError.
  async function api(path, body) {
    const headers = { Accept: 'application/json' };
    const init = { method: 'GET', headers, credentials: 'same-origin', cache: 'no-store' };
    if (body !== undefined) {
      init.method = 'POST';
      headers['Content-Type'] = 'application/json';
      init.body = JSON.stringify(body);
    }
    if (token) headers['X-Cagd-Token'] = token;
    let res;
    try {
      res = await fetch(path, init);
    } catch (e) {
      throw new ApiError('unreachable', '');
    }
    let data = null;
    try {
      data = await res.json();
    } catch (e) {
      data = null;
    }
    if (res.status === 503) throw new ApiError('busy', data && data.message ? String(data.message) : '', 503);
    if (!res.ok || data === null || typeof data !== 'object') {
      const detail = data && (data.error || data.message) ? String(data.message || data.error) : String(res.status);
      throw new ApiError('failed', detail, res.status);
    }
    return data;
  }

  // The sentence an ApiError shows.
  function errorText(err) {
    if (err instanceof ApiError) {
      if (err.kind === 'busy') return word('busy');
      if (err.kind === 'unreachable') return word('unreachable');
      return err.detail ? word('failed') + ' ' + err.detail : word('failed');
    }
    return word('failed') + ' ' + String(err && err.message ? err.message : err);
  }

  function showError(box, err) {
    box.textContent = typeof err === 'string' ? err : errorText(err);
    box.hidden = false;
  }

  function typeset(root) {
    if (!root) return;
    const all = root.matches && root.matches('.math[data-tex]') ? [root] : [];
    root.querySelectorAll('.math[data-tex]').forEach((m) => all.push(m));
    for (const m of all) {
      const tex = m.getAttribute('data-tex') || '';
      if (window.katex) {
        window.katex.render(tex, m, { throwOnError: false, displayMode: m.classList.contains('display') });
      } else {
        m.textContent = tex;
      }
    }
  }

  // One of the API's `*_html` fields (escaped by the server), typeset.
  function setHtml(box, html) {
    box.innerHTML = html || '';
    typeset(box);
  }

  // The page's language: the URL's, else the server's (known after the first answer).
  let lang = urlLang;
  function setLang(l) {
    lang = l === 'es' ? 'es' : 'en';
    document.documentElement.lang = lang;
  }

  function urlWith(changes) {
    const u = new URL(window.location.href);
    for (const [k, v] of Object.entries(changes)) u.searchParams.set(k, v);
    return u.pathname + u.search;
  }

  // The switch "English" / "Español": links that reload the page in the other language.
  function languageSwitch() {
    const nav = el('nav', 'lang-switch');
    nav.setAttribute('aria-label', word('language'));
    nav.appendChild(el('span', 'lang-label', word('language') + ':'));
    for (const [code, id] of [['en', 'english'], ['es', 'spanish']]) {
      const a = el('a', 'lang', word(id));
      a.href = urlWith({ lang: code });
      a.lang = code;
      a.hreflang = code;
      a.setAttribute('data-lang', code);
      if (code === lang) a.setAttribute('aria-current', 'page');
      nav.appendChild(a);
    }
    return nav;
  }

  // ---- the templates ----------------------------------------------------------------------

  function isCell(t) {
    return t !== null && typeof t === 'object' && !Array.isArray(t) &&
      typeof t.cell === 'string' && typeof t.kind === 'string';
  }
  // An array of cells of one entry: a point (its coordinates), or a knot vector.
  function isGroup(t) {
    return Array.isArray(t) && t.length > 0 && t.every(isCell) && t.every((c) => c.cell === t[0].cell);
  }
  function isEntry(t) { return isCell(t) || isGroup(t); }

  let serial = 0;

  // Walks a template and calls leaf(cell, path) for every cell, building the same structure.
  function mapTemplate(t, path, leaf) {
    if (isCell(t)) return leaf(t, path);
    if (Array.isArray(t)) return t.map((x, i) => mapTemplate(x, path.concat([i]), leaf));
    if (t !== null && typeof t === 'object') {
      const out = {};
      for (const k of Object.keys(t)) out[k] = mapTemplate(t[k], path.concat([k]), leaf);
      return out;
    }
    return t;
  }

  // A cell's entry as the page's language names it.
  function entryName(c) {
    return (c.name && typeof c.name[lang] === 'string' && c.name[lang]) || c.cell;
  }

  // The drawing of one result's template: its entries, each a group of cells.
  class ResultView {
    constructor(problem, result, opts) {
      this.problem = problem;
      this.result = result;
      this.opts = opts;
      this.inputs = new Map(); // path (JSON) -> input element
      this.root = el('div', 'result');
      this.root.setAttribute('data-result', result.key);
      const label = el('h4', 'result-label', result.label);
      label.id = 'label-' + (++serial);
      this.root.appendChild(label);
      this.labelId = label.id;
      const body = el('div', 'result-body');
      body.setAttribute('role', 'group');
      body.setAttribute('aria-labelledby', label.id);
      body.appendChild(this.draw(result.template, [], null));
      this.root.appendChild(body);
    }

    draw(t, path, key) {
      if (isEntry(t)) return this.entry(t, path, key);
      if (Array.isArray(t)) {
        if (t.length > 0 && t.every((r) => Array.isArray(r) && r.length > 0 && r.every(isEntry) && !isGroup(r))) {
          return this.grid(t, path);
        }
        if (t.length > 0 && t.every(isCell)) return this.row(t, path, key);
        const list = el('div', 'list');
        t.forEach((x, i) => {
          const item = el('div', 'item');
          item.appendChild(this.draw(x, path.concat([i]), null));
          list.appendChild(item);
        });
        if (t.length > 0 && t.every(isGroup)) list.classList.add('points');
        return list;
      }
      if (t !== null && typeof t === 'object') {
        const fields = el('div', 'fields');
        for (const k of Object.keys(t)) {
          const f = el('div', 'field');
          f.setAttribute('data-key', k);
          // a field of the answer's JSON by the notes' name (`bezier`: puntos de control)
          const named = words['field_' + k];
          f.appendChild(el('div', 'field-key', typeof named === 'string' ? named : k));
          const v = el('div', 'field-value');
          v.appendChild(this.draw(t[k], path.concat([k]), k));
          f.appendChild(v);
          fields.appendChild(f);
        }
        return fields;
      }
      return el('span', 'constant', String(t));
    }

    // A mesh: rows i, columns j.
    grid(t, path) {
      const table = el('table', 'grid');
      const head = el('tr');
      head.appendChild(el('th', 'corner'));
      const cols = Math.max(...t.map((r) => r.length));
      for (let j = 0; j < cols; j++) {
        const th = el('th', 'col-index', 'j = ' + j);
        th.scope = 'col';
        head.appendChild(th);
      }
      const thead = el('thead');
      thead.appendChild(head);
      table.appendChild(thead);
      const tbody = el('tbody');
      t.forEach((r, i) => {
        const tr = el('tr');
        const th = el('th', 'row-index', 'i = ' + i);
        th.scope = 'row';
        tr.appendChild(th);
        r.forEach((x, j) => {
          const td = el('td');
          td.appendChild(this.entry(x, path.concat([i, j]), null));
          tr.appendChild(td);
        });
        tbody.appendChild(tr);
      });
      table.appendChild(tbody);
      return table;
    }

    // Cells of several entries in a row (weights w_0, w_1, ...).
    row(t, path, key) {
      const row = el('div', 'row');
      t.forEach((c, i) => row.appendChild(this.entry(c, path.concat([i]), key)));
      return row;
    }

    // One entry: a lone cell, a point ( _ , _ , _ ), or a knot vector [ _ , _ , ... ].
    entry(t, path, key) {
      const cells = isCell(t) ? [t] : t;
      const id = cells[0].cell;
      const box = el('div', 'entry');
      box.setAttribute('data-entry', id);
      // the entry's name in the page's language (`el valor`), its id when the server sent none
      const caption = el('span', 'entry-id', entryName(cells[0]));
      caption.setAttribute('aria-hidden', 'true');
      box.appendChild(caption);
      const line = el('div', 'entry-cells');
      const knots = key === 'knots';
      const tuple = !isCell(t);
      if (tuple) line.appendChild(el('span', 'paren', knots ? '[' : '('));
      cells.forEach((c, k) => {
        if (tuple && k > 0) line.appendChild(el('span', 'comma', ','));
        line.appendChild(this.slot(c, tuple ? path.concat([k]) : path, tuple ? k : null, cells.length));
      });
      if (tuple) line.appendChild(el('span', 'paren', knots ? ']' : ')'));
      const mark = el('span', 'mark');
      mark.setAttribute('aria-live', 'polite');
      line.appendChild(mark);
      box.appendChild(line);
      if (tuple) box.classList.add(knots ? 'knots' : 'point');
      return box;
    }

    // One cell: its input (or yes/no choice) and, under it, its preview.
    slot(c, path, coord, count) {
      const slot = el('div', 'slot kind-' + c.kind);
      const n = ++serial;
      let input;
      if (c.kind === 'bool') {
        input = el('select', 'cell');
        for (const [v, w] of [['', 'choose'], ['true', 'yes'], ['false', 'no']]) {
          const o = el('option', null, word(w));
          o.value = v;
          input.appendChild(o);
        }
      } else {
        input = el('input', 'cell');
        input.type = 'text';
        input.autocomplete = 'off';
        input.spellcheck = false;
        input.setAttribute('autocapitalize', 'off');
        if (c.kind === 'number') input.inputMode = 'text';
      }
      input.id = 'cell-' + n;
      input.setAttribute('data-cell', c.cell);
      if (coord !== null) input.setAttribute('data-coord', String(coord));
      input.setAttribute('data-kind', c.kind);
      const p = JSON.stringify(path);
      input.setAttribute('data-path', p);
      let name = this.result.label + ': ' + word('entry') + ' ' + entryName(c);
      if (coord !== null && count > 1) name += ', ' + word('coordinate') + ' ' + (coord + 1);
      input.setAttribute('aria-label', name);
      input.title = coord !== null && count > 1 ? entryName(c) + ' [' + (coord + 1) + ']' : entryName(c);
      slot.appendChild(input);
      if (c.kind !== 'bool' && c.kind !== 'text') {
        const preview = el('div', 'preview');
        preview.id = 'preview-' + n;
        preview.setAttribute('aria-live', 'polite');
        input.setAttribute('aria-describedby', preview.id);
        slot.appendChild(preview);
        input.cagdPreview = preview;
      }
      input.cagdCell = c;
      this.inputs.set(p, input);
      return slot;
    }

    // The answer in the template's structure; null when every cell is empty.
    answer() {
      let any = false;
      const out = mapTemplate(this.result.template, [], (c, path) => {
        const input = this.inputs.get(JSON.stringify(path));
        const v = input ? input.value : '';
        if (v.trim() !== '') any = true;
        if (c.kind === 'bool') return v === 'true' ? true : v === 'false' ? false : '';
        return v;
      });
      return any ? out : null;
    }

    // What the browser keeps: path -> text.
    values() {
      const out = {};
      let any = false;
      for (const [p, input] of this.inputs) {
        if (input.value !== '') {
          out[p] = input.value;
          any = true;
        }
      }
      return any ? out : null;
    }

    clearMarks() {
      this.root.querySelectorAll('.entry[data-mark]').forEach((e) => this.unmark(e));
    }

    unmark(e) {
      e.removeAttribute('data-mark');
      e.classList.remove('right', 'wrong');
      const m = e.querySelector('.mark');
      if (m) {
        m.textContent = '';
        m.removeAttribute('title');
        m.removeAttribute('aria-label');
        m.removeAttribute('role');
      }
    }

    mark(entry, right) {
      const sel = '.entry[data-entry="' + CSS.escape(entry) + '"]';
      this.root.querySelectorAll(sel).forEach((e) => {
        e.setAttribute('data-mark', right ? 'right' : 'wrong');
        e.classList.toggle('right', right);
        e.classList.toggle('wrong', !right);
        const m = e.querySelector('.mark');
        if (m) {
          m.textContent = right ? '✓' : '✗';
          m.title = word(right ? 'correct' : 'wrong');
          m.setAttribute('role', 'img');
          m.setAttribute('aria-label', word(right ? 'correct' : 'wrong'));
        }
      });
    }
  }

  // At most two cell readings at a time (the server's pool is small).
  const readQueue = [];
  let reading = 0;
  function queueRead(job) {
    readQueue.push(job);
    pump();
  }
  function pump() {
    while (reading < 2 && readQueue.length > 0) {
      const job = readQueue.shift();
      reading++;
      job().finally(() => {
        reading--;
        pump();
      });
    }
  }

  // A cell's preview: what the engine read, typeset; or why it does not read.
  function readCell(problemIndex, input, immediate) {
    const preview = input.cagdPreview;
    if (!preview) return;
    clearTimeout(input.cagdTimer);
    const seq = (input.cagdSeq || 0) + 1;
    input.cagdSeq = seq;
    const text = input.value;
    if (text.trim() === '') {
      preview.textContent = '';
      preview.classList.remove('error', 'busy');
      input.removeAttribute('aria-invalid');
      return;
    }
    const run = () => queueRead(async () => {
      if (input.cagdSeq !== seq) return;
      let data;
      try {
        data = await api('/api/read', { problem: problemIndex, text, kind: input.cagdCell.kind, lang });
      } catch (err) {
        if (input.cagdSeq !== seq) return;
        preview.classList.remove('error');
        preview.classList.add('busy');
        preview.textContent = errorText(err);
        return;
      }
      if (input.cagdSeq !== seq) return;
      preview.classList.remove('busy');
      if (data.ok) {
        preview.classList.remove('error');
        input.removeAttribute('aria-invalid');
        preview.textContent = '';
        if (window.katex) {
          window.katex.render(String(data.tex || ''), preview, { throwOnError: false, displayMode: false });
        } else {
          preview.textContent = String(data.tex || '');
        }
      } else {
        preview.classList.add('error');
        input.setAttribute('aria-invalid', 'true');
        preview.textContent = data.error ? String(data.error) : word('read_error');
      }
    });
    if (immediate) run();
    else input.cagdTimer = setTimeout(run, 250);
  }

  // ---- a problem set ------------------------------------------------------------------------

  function storageKey(title, index, key) {
    return 'cagd:' + JSON.stringify([title, index, key]);
  }
  function storageGet(k) {
    try {
      const s = window.localStorage.getItem(k);
      return s ? JSON.parse(s) : null;
    } catch (e) {
      return null;
    }
  }
  function storageSet(k, v) {
    try {
      if (v === null) window.localStorage.removeItem(k);
      else window.localStorage.setItem(k, JSON.stringify(v));
    } catch (e) {
      // a browser that keeps nothing: the answers live as long as the page
    }
  }

  // Draws a set (the JSON of /api/set) into container. opts.interactive: the cells are
  // read and checked against the served set, and kept in localStorage.
  function drawSet(container, set, opts) {
    const interactive = !!(opts && opts.interactive);
    container.textContent = '';
    const views = [];
    for (const problem of set.problems || []) {
      const sec = el('section', 'problem');
      sec.setAttribute('data-problem', String(problem.index));
      sec.id = (interactive ? 'problem-' : 'preview-problem-') + problem.index;
      sec.appendChild(el('h2', 'problem-title', problem.title));
      const st = el('div', 'statement');
      setHtml(st, problem.statement_html);
      sec.appendChild(st);
      if (problem.figure) {
        const fig = el('figure', 'figure');
        const img = el('img');
        const src = String(problem.figure);
        img.src = src.startsWith('data:') || src.includes('lang=') ? src
          : src + (src.includes('?') ? '&' : '?') + 'lang=' + encodeURIComponent(set.lang || lang);
        img.alt = word('figure') + ' ' + problem.title;
        img.loading = 'lazy';
        fig.appendChild(img);
        sec.appendChild(fig);
      }
      const answer = el('div', 'answer');
      answer.appendChild(el('h3', 'answer-heading', word('your_answer')));
      const results = [];
      for (const result of problem.results || []) {
        const view = new ResultView(problem, result, opts);
        results.push(view);
        answer.appendChild(view.root);
      }
      sec.appendChild(answer);
      const pv = { problem, results, section: sec };
      views.push(pv);
      if (interactive) wire(pv, set);
      container.appendChild(sec);
    }
    return views;
  }

  function wire(pv, set) {
    const { problem, results, section } = pv;
    const title = set.title || '';
    const bar = el('div', 'buttons');
    const check = el('button', 'check', word('check'));
    check.type = 'button';
    const clear = el('button', 'clear', word('clear'));
    clear.type = 'button';
    const status = el('span', 'status');
    status.setAttribute('role', 'status');
    bar.append(check, clear, status);
    section.appendChild(bar);
    const error = el('div', 'message error');
    error.setAttribute('role', 'alert');
    error.hidden = true;
    section.appendChild(error);
    const outcome = el('div', 'outcome');
    outcome.hidden = true;
    section.appendChild(outcome);

    for (const view of results) {
      const k = storageKey(title, problem.index, view.result.key);
      const kept = storageGet(k);
      if (kept && typeof kept === 'object') {
        for (const [p, v] of Object.entries(kept)) {
          const input = view.inputs.get(p);
          if (input && typeof v === 'string') {
            input.value = v;
            readCell(problem.index, input, true);
          }
        }
      }
      for (const input of view.inputs.values()) {
        const changed = () => {
          storageSet(k, view.values());
          const entry = input.closest('.entry');
          if (entry && entry.hasAttribute('data-mark')) view.unmark(entry);
          readCell(problem.index, input, false);
        };
        input.addEventListener('input', changed);
        if (input.tagName === 'SELECT') input.addEventListener('change', changed);
      }
    }

    clear.addEventListener('click', () => {
      for (const view of results) {
        for (const input of view.inputs.values()) {
          input.value = '';
          readCell(problem.index, input, true);
        }
        view.clearMarks();
        storageSet(storageKey(title, problem.index, view.result.key), null);
      }
      outcome.hidden = true;
      outcome.textContent = '';
      error.hidden = true;
    });

    check.addEventListener('click', async () => {
      const answer = {};
      for (const view of results) {
        const a = view.answer();
        if (a !== null) answer[view.result.key] = a;
      }
      check.disabled = true;
      status.textContent = word('checking');
      error.hidden = true;
      let data;
      try {
        data = await api('/api/check', { problem: problem.index, answer, lang });
      } catch (err) {
        showError(error, err);
        return;
      } finally {
        check.disabled = false;
        status.textContent = '';
      }
      showOutcome(outcome, results, data);
    });
  }

  function showOutcome(outcome, results, data) {
    outcome.textContent = '';
    const verdict = ['correct', 'wrong', 'unreadable'].includes(data.verdict) ? data.verdict : 'unreadable';
    const v = el('div', 'verdict');
    v.setAttribute('data-verdict', verdict);
    const sign = { correct: '✓', wrong: '✗', unreadable: '?' }[verdict];
    const badge = el('span', 'badge', sign + ' ' + word(verdict));
    v.appendChild(badge);
    v.appendChild(el('span', 'summary', data.summary || ''));
    outcome.appendChild(v);
    if (data.score !== null && data.score !== undefined) {
      const s = el('p', 'score');
      s.appendChild(el('span', 'score-label', word('score') + ': '));
      s.appendChild(el('span', 'score-value', String(data.score)));
      outcome.appendChild(s);
    }
    if (Array.isArray(data.diagnoses) && data.diagnoses.length > 0) {
      const box = el('div', 'diagnoses');
      box.appendChild(el('h3', null, word('diagnosis')));
      const ul = el('ul');
      for (const d of data.diagnoses) {
        const li = el('li', 'diagnosis');
        li.setAttribute('data-id', String(d.id || ''));
        li.appendChild(el('span', 'said', d.said || ''));
        if (d.place) li.appendChild(el('span', 'place', d.place));
        ul.appendChild(li);
      }
      box.appendChild(ul);
      outcome.appendChild(box);
    }
    if (data.report_html) {
      const det = el('details', 'report-box');
      det.open = true;
      det.appendChild(el('summary', null, word('report')));
      const r = el('div', 'report');
      setHtml(r, data.report_html);
      det.appendChild(r);
      outcome.appendChild(det);
    }
    if (data.solution_html) {
      const det = el('details', 'solution-box');
      det.open = true;
      det.appendChild(el('summary', null, word('solution')));
      const s = el('div', 'solution');
      setHtml(s, data.solution_html);
      det.appendChild(s);
      outcome.appendChild(det);
    }
    for (const view of results) view.clearMarks();
    const byKey = new Map(results.map((r) => [r.result.key, r]));
    for (const m of Array.isArray(data.marks) ? data.marks : []) {
      const view = byKey.get(m.result);
      if (view) view.mark(String(m.cell), m.right === true);
    }
    outcome.hidden = false;
  }

  return { token, el, api, errorText, showError, typeset, setHtml, setWords, word, setLang,
    get lang() { return lang; }, languageSwitch, drawSet, urlWith, ApiError };
})();
