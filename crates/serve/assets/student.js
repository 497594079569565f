// cagd serve: the student's page. Loads the set (/api/set), draws it with common.js, and
// checks each problem's answer (/api/check).
'use strict';

(async () => {
  const top = document.getElementById('top');
  const main = document.getElementById('set');
  const status = Cagd.el('p', 'status');
  status.setAttribute('role', 'status');
  main.appendChild(status);
  const q = Cagd.lang ? '?lang=' + encodeURIComponent(Cagd.lang) : '';
  let set;
  try {
    set = await Cagd.api('/api/set' + q);
  } catch (err) {
    const box = Cagd.el('div', 'message error');
    box.setAttribute('role', 'alert');
    Cagd.showError(box, err);
    main.textContent = '';
    main.appendChild(box);
    return;
  }
  Cagd.setWords(set.words);
  Cagd.setLang(set.lang || Cagd.lang);
  document.title = set.title || Cagd.word('student_title');
  top.textContent = '';
  top.appendChild(Cagd.languageSwitch());
  const h1 = Cagd.el('h1', 'set-title', set.title || Cagd.word('student_title'));
  h1.id = 'set-title';
  top.appendChild(h1);
  top.appendChild(Cagd.el('p', 'note kept', Cagd.word('kept_here')));
  main.textContent = '';
  Cagd.drawSet(main, set, { interactive: true });
})();
