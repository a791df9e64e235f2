'use strict';
// The Concord console: plain JavaScript, no build step. Every text from the platform goes in by
// textContent, never as HTML.
(function () {
  const token = new URLSearchParams(location.search).get('token');
  const SVG = 'http://www.w3.org/2000/svg';
  const $ = (id) => document.getElementById(id);
  const state = { tab: 'platform', platform: null, safety: null, views: [], view: null, sniffed: [], picked: new Set(),
    conversation: '', source: null, safetyPick: null };

  function url(path, params) {
    const u = new URL(path, location.href);
    for (const [k, v] of Object.entries(params || {})) { if (v !== '' && v != null) u.searchParams.set(k, v); }
    if (token) u.searchParams.set('token', token);
    return u.toString();
  }
  function el(tag, text, cls) {
    const e = document.createElement(tag);
    if (text != null) e.textContent = text;
    if (cls) e.className = cls;
    return e;
  }
  function svg(tag, attrs, text) {
    const e = document.createElementNS(SVG, tag);
    for (const [k, v] of Object.entries(attrs || {})) e.setAttribute(k, v);
    if (text != null) e.textContent = text;
    return e;
  }
  // Now, or while a recording is played back, the time the slider says.
  function now() {
    return state.replay ? state.replay.at : Date.now();
  }
  function ago(ms) {
    if (!ms) return '';
    const s = Math.max(0, Math.round((now() - ms) / 1000));
    return s < 120 ? s + ' s ago' : Math.round(s / 60) + ' min ago';
  }
  // A time since, that goes on ticking between the platform's events.
  function agoEl(ms) {
    const e = el('span', ago(ms), 'ago');
    e.dataset.ms = ms || '';
    return e;
  }
  setInterval(() => document.querySelectorAll('span.ago').forEach((e) => { e.textContent = ago(Number(e.dataset.ms)); }), 1000);

  // ---- the event stream: one per page, every topic whatever the tab -----------------------------
  // A tab switch neither reconnects nor clears: what the sniffer saw while another tab was shown
  // is there when it is shown again. Only a new choice of agents or conversation starts a new story.
  function topics() {
    return ['platform', 'safety', 'sniff', 'mail'].concat(state.views.map((v) => 'view-' + v.id)).join(',');
  }
  function connect(fresh) {
    if (state.source) state.source.close();
    if (fresh) {
      state.sniffed = [];
      drawDiagram();
    }
    const src = new EventSource(url('api/events', { topics: topics(), sniff: [...state.picked].join(','),
      conversation: state.conversation }));
    state.source = src;
    src.onopen = () => { $('status').textContent = 'live'; $('status').className = 'status'; };
    src.onerror = () => {
      $('status').textContent = 'reconnecting…';
      $('status').className = 'status down';
      // Refused (too many browsers) or the server restarted: the browser gives up; try again.
      if (src.readyState === EventSource.CLOSED && state.source === src) setTimeout(() => { if (state.source === src) connect(); }, 1000);
    };
    src.addEventListener('platform', (e) => { state.platform = JSON.parse(e.data); drawPlatform(); });
    src.addEventListener('safety', (e) => { state.safety = JSON.parse(e.data); drawSafety(); drawPlatform(); });
    src.addEventListener('mail', (e) => drawMail(JSON.parse(e.data)));
    drawMail([]);
    src.addEventListener('sniff', (e) => {
      state.sniffed.push(JSON.parse(e.data));
      if (state.sniffed.length > 500) state.sniffed.shift();
      drawDiagram();
    });
    for (const v of state.views) {
      src.addEventListener('view-' + v.id, (e) => { if (state.view && state.view.id === v.id) drawScene(JSON.parse(e.data)); });
    }
  }

  // ---- tabs -----------------------------------------------------------------------------------
  function show(tab, view) {
    state.tab = tab;
    state.view = view || null;
    document.querySelectorAll('nav button').forEach((b) => b.classList.toggle('active',
      b.dataset.tab === tab && (!view || b.dataset.view === view.id)));
    document.querySelectorAll('.tab').forEach((s) => s.classList.toggle('active', s.id === tab));
    if (tab === 'bench') loadBench();
    if (tab === 'replay') loadRecordings();
    if (state.replay) replayAt(state.replay.at);
    if (tab === 'view') drawForm();
    if (tab === 'sniffer') drawDiagram();
  }
  document.querySelectorAll('nav button[data-tab]').forEach((b) => b.addEventListener('click', () => show(b.dataset.tab)));

  // ---- platform -------------------------------------------------------------------------------
  function matches(a, q) {
    if (!q) return true;
    q = q.toLowerCase();
    return a.services.some((s) => (s.type || '').toLowerCase().includes(q) || (s.name || '').toLowerCase().includes(q));
  }
  // Where an agent runs and how it is doing, from its own last report (the safety event).
  function figures(name) {
    const s = state.safety;
    return s ? s.agents.find((x) => x.agent === name) : null;
  }
  // Every action the console asks of the server: a form's fields POSTed with the console's header;
  // the answer's message (or the error's text) is shown in the element `said`. True if it went well.
  function post(path, params, said) {
    return fetch(url(path), { method: 'POST', body: new URLSearchParams(params), headers: { 'X-Concord-Console': '1' } })
      .then((r) => r.text().then((t) => { $(said).textContent = r.ok ? JSON.parse(t).message : t; return r.ok; }));
  }
  function act(action, params, said) {
    return post('api/agents/' + action, params, said || 'agent-said');
  }
  // One table, grouped as JADE's RMA groups its tree: by host, then by JVM (process id).
  function drawAgents(p, q) {
    const tbody = $('agents').tBodies[0];
    const groups = new Map();
    let n = 0;
    for (const [a, where] of p.lal.map((a) => [a, 'local']).concat(p.gal.map((a) => [a, 'global']))) {
      if (!matches(a, q)) continue;
      n++;
      const f = figures(a.name);
      const key = f && f.host ? 'host ' + f.host + ' · JVM ' + f.pid : 'where it runs not reported yet';
      if (!groups.has(key)) groups.set(key, []);
      groups.get(key).push([a, where, f]);
    }
    const sorted = [...groups.entries()].sort((x, y) => x[0].localeCompare(y[0]));
    // Only the figures changed (every two seconds): they are written in place, so that a button the
    // operator is about to click is not replaced under the pointer.
    const shape = JSON.stringify(sorted.map(([k, l]) => [k, l.map(([a, w]) => [a.name, w, a.address, a.startMs, a.services, a.name === p.container])]));
    if (tbody.dataset.shape === shape) {
      for (const [, list] of sorted) {
        for (const [a, , f] of list) {
          const tr = [...tbody.rows].find((r) => r.dataset.agent === a.name);
          if (!tr || !f) continue;
          tr.cells[4].textContent = f.received + ' / ' + f.sent;
          tr.cells[5].textContent = f.mailbox >= 0 ? String(f.mailbox) : '';
          tr.cells[6].textContent = f.lagMs + ' ms';
        }
      }
      return n;
    }
    tbody.dataset.shape = shape;
    tbody.replaceChildren();
    for (const [key, list] of sorted) {
      const g = el('tr', null, 'group');
      const td = el('td', key + ' — ' + list.length + (list.length === 1 ? ' agent' : ' agents'));
      td.colSpan = 8;
      g.appendChild(td);
      g.dataset.group = key;
      tbody.appendChild(g);
      for (const [a, where, f] of list) {
        const tr = el('tr');
        tr.dataset.agent = a.name;
        tr.dataset.list = where;
        tr.dataset.group = key;
        const name = el('td', a.name);
        if (a.name === p.container) name.appendChild(el('span', 'container', 'container-tag'));
        tr.appendChild(name);
        tr.appendChild(el('td', a.address));
        const s = el('td');
        for (const d of a.services) s.appendChild(el('span', d.type + (d.name ? ': ' + d.name : ''), 'svc'));
        tr.appendChild(s);
        const since = el('td');
        since.appendChild(agoEl(a.startMs));
        tr.appendChild(since);
        tr.appendChild(el('td', f ? f.received + ' / ' + f.sent : '', 'num'));
        tr.appendChild(el('td', f && f.mailbox >= 0 ? String(f.mailbox) : '', 'num'));
        tr.appendChild(el('td', f ? f.lagMs + ' ms' : '', 'num'));
        const acts = el('td');
        if (a.name !== p.console) {
          const k = el('button', 'Kill', 'kill');
          k.type = 'button';
          k.addEventListener('click', () => {
            if (confirm('Kill ' + a.name + '? Its takeDown() runs and it leaves the platform.')) act('kill', { agent: a.name });
          });
          const m = el('button', 'Message', 'message');
          m.type = 'button';
          m.addEventListener('click', () => { $('send-to').value = a.name; $('send-to').focus(); });
          acts.appendChild(k);
          acts.appendChild(m);
        }
        tr.appendChild(acts);
        tbody.appendChild(tr);
      }
    }
    return n;
  }
  function formParams(form) {
    const o = {};
    for (const e of form.elements) if (e.name) o[e.name] = e.value;
    return o;
  }
  $('start-agent').addEventListener('click', () => act('start', formParams($('start-form'))));
  $('send-message').addEventListener('click', () => act('send', formParams($('send-form'))));
  // JADE's DummyAgent's habits: save the message as a file, load a saved one, reply to one received.
  // The console's agent writes and reads FIPA's string form (its own codec), so a file is one JADE reads too.
  function agentJson(action, params) {
    return fetch(url('api/agents/' + action), { method: 'POST', body: new URLSearchParams(params), headers: { 'X-Concord-Console': '1' } })
      .then((r) => r.text().then((t) => {
        if (!r.ok) { $('agent-said').textContent = t; throw new Error(t); }
        return JSON.parse(t).message;
      }));
  }
  function fillSendForm(f) {
    const form = $('send-form');
    for (const k of ['performative', 'receivers', 'content', 'conversation', 'language', 'ontology', 'protocol', 'in-reply-to']) {
      form.elements[k].value = f[k] || '';
    }
  }
  $('save-message').addEventListener('click', () => agentJson('compose', formParams($('send-form'))).then((text) => {
    const a = $('saved-message');
    if (a.href) URL.revokeObjectURL(a.href);
    a.href = URL.createObjectURL(new Blob([text + '\n'], { type: 'text/plain' }));
    a.download = 'message.acl';
    a.dataset.text = text;
    a.click();
    $('agent-said').textContent = 'saved as message.acl (' + text.length + ' characters, FIPA ACL string form)';
  }).catch(() => {}));
  $('load-message').addEventListener('change', (e) => {
    const file = e.target.files[0];
    if (!file) return;
    file.text().then((text) => agentJson('parse', { text: text })).then((m) => {
      fillSendForm(JSON.parse(m));
      $('agent-said').textContent = 'loaded ' + file.name + ': edit it or press Send';
    }).catch(() => {}).finally(() => { e.target.value = ''; });
  });
  function replyTo(message) {
    agentJson('parse', { text: message }).then((m) => {
      const f = JSON.parse(m);
      // As JADE's createReply: to the sender, the same conversation, language, ontology and protocol, in reply to its reply-with.
      fillSendForm({ performative: f.performative, receivers: f.sender, content: '', conversation: f.conversation,
        language: f.language, ontology: f.ontology, protocol: f.protocol, 'in-reply-to': f['reply-with'] });
      $('agent-said').textContent = 'a reply to ' + f.sender + ': choose its performative and content, then Send';
      $('send-form').elements.content.focus();
    }).catch(() => {});
  }
  function drawMail(list) {
    const tbody = $('mail').tBodies[0];
    tbody.replaceChildren();
    if (!list.length) {
      const td = el('td', 'Nothing yet: send a message above, and its answers come here.', 'hint');
      td.colSpan = 7;
      tbody.appendChild(el('tr')).appendChild(td);
    }
    for (const m of list.slice().reverse()) {
      const tr = el('tr', null, 'pick');
      tr.dataset.dir = m.dir;
      tr.dataset.performative = m.performative;
      tr.appendChild(el('td', clock(m.atMs)));
      tr.appendChild(el('td', m.dir));
      tr.appendChild(el('td', m.performative));
      tr.appendChild(el('td', m.from));
      tr.appendChild(el('td', m.conversation));
      const c = /:content\s+"((?:[^"\\]|\\.)*)"/.exec(m.message);
      // The content as its sender meant it (escapes undone), cut to a line; the whole message in the row's title.
      const text = c ? c[1].replace(/\\(.)/g, '$1') : '';
      tr.appendChild(el('td', text.length > 120 ? text.slice(0, 117) + '…' : text, 'content'));
      const act = tr.appendChild(el('td'));
      if (m.dir === 'received') {
        const b = act.appendChild(el('button', 'Reply', 'reply'));
        b.type = 'button';
        b.addEventListener('click', (e) => { e.stopPropagation(); replyTo(m.message); });
      }
      tr.title = m.message;
      tbody.appendChild(tr);
    }
  }
  function drawPlatform() {
    const p = state.platform;
    if (!p) return;
    $('platform-name').textContent = 'platform ' + p.platform;
    const box = $('container-box');
    box.replaceChildren();
    box.appendChild(el('strong', p.container ? 'Container: ' + p.container : 'No container elected yet'));
    if (p.container) {
      box.appendChild(el('span', ' — term ' + p.term + ', since '));
      box.appendChild(agoEl(p.containerSinceMs));
    }
    box.appendChild(el('div', 'This console is ' + p.console + ' (' + p.role.toLowerCase() + ').', 'hint'));
    const q = $('search').value.trim();
    const n = drawAgents(p, q);
    $('lal-count').textContent = p.lal.length;
    $('gal-count').textContent = p.gal.length;
    $('search-count').textContent = q ? n + ' agents offer a matching service' : (p.lal.length + p.gal.length) + ' agents';
    const f = $('facilitators');
    f.replaceChildren();
    for (const x of p.facilitators) f.appendChild(el('li', x));
    if (!p.facilitators.length) f.appendChild(el('li', 'none', 'hint'));
    drawPicker();
  }
  $('search').addEventListener('input', drawPlatform);

  // ---- safety ---------------------------------------------------------------------------------
  function drawSafety() {
    const s = state.safety;
    if (!s) return;
    const head = $('safety-table').tHead;
    head.replaceChildren();
    const hr = el('tr');
    ['agent', 'role', 'clock offset'].forEach((h) => hr.appendChild(el('th', h)));
    for (const t of s.threats) hr.appendChild(el('th', t));
    head.appendChild(hr);
    const body = $('safety-table').tBodies[0];
    body.replaceChildren();
    for (const a of s.agents) {
      const tr = el('tr', null, 'pick');
      tr.dataset.agent = a.agent;
      tr.appendChild(el('td', a.agent));
      tr.appendChild(el('td', a.role.toLowerCase()));
      tr.appendChild(el('td', a.clockSynced ? (a.clockOffsetUs / 1000).toFixed(1) + ' ms' : 'own clock', 'num'));
      for (const t of s.threats) {
        const td = el('td', a.threats[t] + (a.perMinute[t] ? ' (+' + a.perMinute[t] + ' /min)' : ''), 'num');
        if (a.perMinute[t]) td.title = a.perMinute[t] + ' in the last minute';
        td.dataset.threat = t;
        // Copies the stack sends on purpose, and another platform's frames skipped, are shown apart, in grey: never an alarm.
        if ((s.expected || [s.threats[0]]).includes(t)) td.classList.add('expected');
        else if (a.perMinute[t] > 0) td.classList.add('hot');
        tr.appendChild(td);
      }
      tr.addEventListener('click', () => {
        state.safetyPick = a.agent;
        drawSafetyDetail();
        $('safety-detail').scrollIntoView({ block: 'nearest' });
      });
      body.appendChild(tr);
    }
    drawSafetyDetail();
    drawThreatRate(s);
    $('safety-console').textContent = 'The console itself: ' + s.consoleDrops + ' events dropped for slow browsers, '
      + s.consoleMalformed + ' malformed reports.';
  }
  // The platform's real threats a minute (every agent's, the copies sent on purpose left out), as a
  // line over the last samples, and an alarm when they reach what the operator set.
  state.rate = [];
  function drawThreatRate(s) {
    const byThreat = {};
    let now = 0;
    for (const a of s.agents) {
      for (const t of s.threats) {
        if (t === 'other' || (s.expected || [s.threats[0]]).includes(t)) continue;
        now += a.perMinute[t] || 0;
        byThreat[t] = (byThreat[t] || 0) + (a.perMinute[t] || 0);
      }
    }
    state.rate.push(now);
    if (state.rate.length > 120) state.rate.shift();
    const at = Math.max(1, Number($('safety-alarm-at').value) || 20);
    const top = Math.max(at * 1.25, ...state.rate);
    const g = $('safety-rate');
    g.replaceChildren();
    const y = (v) => 56 - 52 * v / top;
    g.appendChild(svg('line', { x1: 0, y1: y(at), x2: 600, y2: y(at), stroke: '#c0392b', 'stroke-dasharray': '4 3' }));
    g.appendChild(svg('polyline', { points: state.rate.map((v, i) => (i * 5) + ',' + y(v)).join(' '), fill: 'none',
      stroke: '#2d6cb5', 'stroke-width': 2, id: 'safety-rate-line' }));
    const alarm = $('safety-alarm');
    alarm.hidden = now < at;
    alarm.textContent = now < at ? '' : 'Alarm: ' + now + ' threats in the last minute (' + Object.entries(byThreat)
      .filter(([, v]) => v > 0).map(([t, v]) => t + ' ' + v).join(', ') + '); the table says which agents';
  }
  function drawSafetyDetail() {
    const s = state.safety;
    const a = s && s.agents.find((x) => x.agent === state.safetyPick);
    if (!a) { $('safety-detail').textContent = ''; return; }
    const lines = [a.agent + ' — drops by layer and reason:'];
    for (const [layer, reasons] of Object.entries(a.layers)) {
      for (const [r, v] of Object.entries(reasons)) lines.push('  ' + layer + ' / ' + r + ' (' + a.threatOf[r] + '): ' + v);
    }
    if (lines.length === 1) lines.push('  none');
    $('safety-detail').textContent = lines.join('\n');
  }

  // ---- sniffer --------------------------------------------------------------------------------
  function drawPicker() {
    const p = state.platform;
    const box = $('sniff-agents');
    const names = p ? p.lal.concat(p.gal).map((a) => a.name).filter((n) => n !== p.console) : [];
    if (box.dataset.names === names.join(',')) return;
    box.dataset.names = names.join(',');
    box.replaceChildren();
    for (const n of names) {
      const l = el('label', null, 'sniff-pick');
      const c = el('input');
      c.type = 'checkbox';
      c.value = n;
      c.checked = state.picked.has(n);
      c.addEventListener('change', () => {
        if (c.checked) state.picked.add(n); else state.picked.delete(n);
        connect(true);
      });
      l.appendChild(c);
      l.appendChild(document.createTextNode(' ' + n));
      box.appendChild(l);
    }
  }
  $('sniff-conversation').addEventListener('change', (e) => { state.conversation = e.target.value.trim(); connect(true); });
  $('sniff-clear').addEventListener('click', () => { state.sniffed = []; drawDiagram(); $('message').textContent = ''; });

  $('sniff-filter').addEventListener('input', () => drawDiagram());

  function visible() {
    // A message seen by both its agents is drawn once: as sent, or as received if its sender is not sniffed.
    const sniffedAgents = new Set(state.sniffed.map((m) => m.by));
    // "show only": a performative (AGREE) or a part of an agent's name, without a new stream.
    const only = $('sniff-filter').value.trim().toLowerCase();
    return state.sniffed.filter((m) => m.dir === 'sent' || !sniffedAgents.has(m.from) || state.conversation)
      .filter((m) => !only || m.performative.toLowerCase() === only || m.from.toLowerCase().includes(only)
        || m.to.toLowerCase().includes(only));
  }
  // The time a message was seen, to the millisecond, in the browser's time zone.
  function clock(ms) {
    if (!ms) return '';
    const t = new Date(ms);
    const two = (n) => String(n).padStart(2, '0');
    return two(t.getHours()) + ':' + two(t.getMinutes()) + ':' + two(t.getSeconds()) + '.' + String(t.getMilliseconds()).padStart(3, '0');
  }
  function drawDiagram() {
    const d = $('diagram');
    const wrap = $('diagram-wrap');
    // Follows the story as it grows, unless the reader has scrolled up to read (then it stays put).
    const follow = wrap.scrollTop + wrap.clientHeight >= wrap.scrollHeight - 30;
    d.replaceChildren();
    const msgs = visible().filter((m, i, all) => m.dir === 'sent' || !all.some((o) => o.dir === 'sent'
      && o.from === m.from && o.to === m.to && o.message === m.message));
    // The agents picked have a lifeline each; everybody they talk to shares one, "other agents"
    // (JADE's sniffer does the same), so that a busy agent's story stays as wide as the page.
    const OTHERS = 'other agents';
    const grouped = state.picked.size > 0 && !state.conversation;
    const lane = (a) => (grouped && !state.picked.has(a) ? OTHERS : a);
    const lanes = [];
    for (const a of [...state.picked]) if (!lanes.includes(a)) lanes.push(a);
    for (const m of msgs) for (const a of [m.from, m.to]) if (!lanes.includes(lane(a))) lanes.push(lane(a));
    // The lifelines' names in a header of their own, which stays at the top as the story scrolls.
    const W = 170, head = 34, top = 6, step = 28, T = 90;
    const height = top + 20 + msgs.length * step;
    const width = Math.max(400, T + lanes.length * W + 40);
    const h = $('diagram-head');
    h.replaceChildren();
    h.setAttribute('width', width);
    h.setAttribute('height', head);
    d.setAttribute('width', width);
    d.setAttribute('height', Math.max(86, height));
    lanes.forEach((a, i) => {
      const x = T + 20 + i * W + W / 2;
      h.appendChild(svg('rect', { x: x - 75, y: 5, width: 150, height: 24, rx: 4, fill: '#e3effd', stroke: '#7aa7d6' }));
      h.appendChild(svg('text', { x: x, y: 21, 'text-anchor': 'middle', class: 'lifeline', 'data-agent': a }, a === OTHERS ? a : a.split('@')[0]));
      h.appendChild(svg('line', { x1: x, y1: 29, x2: x, y2: head, stroke: '#b9c2d0', 'stroke-dasharray': '4 3' }));
      d.appendChild(svg('line', { x1: x, y1: 0, x2: x, y2: Math.max(86, height), stroke: '#b9c2d0', 'stroke-dasharray': '4 3' }));
    });
    msgs.forEach((m, i) => {
      const y = top + 10 + i * step;
      const x1 = T + 20 + lanes.indexOf(lane(m.from)) * W + W / 2;
      const x2 = T + 20 + lanes.indexOf(lane(m.to)) * W + W / 2;
      const other = lane(m.from) === OTHERS ? m.from : lane(m.to) === OTHERS ? m.to : null;
      const g = svg('g', { class: 'arrow', 'data-performative': m.performative, 'data-at': clock(m.atMs) });
      g.appendChild(svg('text', { x: 6, y: y + 4, fill: '#7b8494', class: 'at' }, clock(m.atMs)));
      const color = /FAILURE|REFUSE|NOT-UNDERSTOOD/.test(m.performative) ? '#c0392b' : '#2d6cb5';
      g.appendChild(svg('line', { x1: x1, y1: y, x2: x2 + (x2 > x1 ? -6 : 6), y2: y, stroke: color, 'stroke-width': 1.6 }));
      const dir = x2 > x1 ? -1 : 1;
      g.appendChild(svg('polygon', { points: `${x2},${y} ${x2 + dir * 8},${y - 4} ${x2 + dir * 8},${y + 4}`, fill: color }));
      g.appendChild(svg('text', { x: (x1 + x2) / 2, y: y - 4, 'text-anchor': 'middle', fill: color },
        m.performative + (m.conversation ? ' · ' + m.conversation : '') + (other ? ' · ' + (lane(m.from) === OTHERS ? 'from ' : 'to ')
          + other.split('@')[0] : '') + (m.missed ? ' (+' + m.missed + ' missed)' : '')));
      g.addEventListener('click', () => { $('message').textContent = clock(m.atMs) + '  ' + m.dir + ' by ' + m.by + '\n' + m.message; });
      d.appendChild(g);
    });
    if (follow) wrap.scrollTop = wrap.scrollHeight;
    // What is drawn, as a picture: the lifelines' header over the diagram, in one SVG file.
    const pic = document.createElementNS(SVG, 'svg');
    pic.setAttribute('xmlns', SVG);
    pic.setAttribute('width', width);
    pic.setAttribute('height', head + Math.max(86, height));
    pic.appendChild(svg('style', {}, 'text { font: 12px sans-serif; }'));
    pic.appendChild(svg('rect', { width: '100%', height: '100%', fill: '#ffffff' }));
    const top1 = svg('g', {});
    for (const c of h.childNodes) top1.appendChild(c.cloneNode(true));
    const body = svg('g', { transform: 'translate(0,' + head + ')' });
    for (const c of d.childNodes) body.appendChild(c.cloneNode(true));
    pic.append(top1, body);
    $('sniff-export-svg').href = 'data:image/svg+xml;charset=utf-8,' + encodeURIComponent(new XMLSerializer().serializeToString(pic));
    // What is drawn, as text: each message's time, who saw it, and the message in FIPA's string form.
    $('sniff-export').href = 'data:text/plain;charset=utf-8,' + encodeURIComponent(msgs.map((m) => clock(m.atMs) + '  '
      + m.dir + ' by ' + m.by + '\n' + m.message).join('\n\n') + '\n');
  }

  // ---- application views (the hospital) -------------------------------------------------------
  function loadViews() {
    fetch(url('api/views')).then((r) => r.json()).then((vs) => {
      // A view a recording brought (opened before this answer came) keeps its tab.
      state.views = vs.concat(state.views.filter((v) => !vs.some((w) => w.id === v.id)));
      vs = state.views;
      const box = $('view-tabs');
      box.replaceChildren();
      for (const v of vs) {
        const b = el('button', v.title);
        b.dataset.tab = 'view';
        b.dataset.view = v.id;
        b.addEventListener('click', () => show('view', v));
        box.appendChild(b);
      }
      connect(true);
    });
  }
  function drawForm() {
    const f = $('view-form');
    f.replaceChildren();
    $('view-said').textContent = '';
    f.dataset.fields = '';
  }
  function ensureForm(scene) {
    const f = $('view-form');
    const forms = scene.forms || [];
    const key = JSON.stringify(forms);
    if (f.dataset.fields === key) return;
    f.dataset.fields = key;
    f.replaceChildren();
    for (const form of forms) {
      f.appendChild(el('h3', form.title));
      for (const fl of form.fields) {
        const l = el('label', fl.label + ' ');
        const i = el('input');
        i.name = fl.name;
        i.value = fl.value != null ? fl.value : '';
        l.appendChild(i);
        f.appendChild(l);
      }
      const b = el('button', form.button);
      b.type = 'button';
      b.id = 'action-' + form.action;
      b.addEventListener('click', () => {
        const body = new URLSearchParams();
        for (const fl of form.fields) body.set(fl.name, f.elements[fl.name].value);
        viewAction(form.action, body);
      });
      f.appendChild(b);
    }
  }
  function drawScene(scene) {
    ensureForm(scene);
    const s = $('view-scene');
    const [x0, y0, x1, y1] = scene.bounds;
    // y grows up in the world, down on the screen: flip it.
    s.setAttribute('viewBox', `${x0} ${-y1} ${x1 - x0} ${y1 - y0}`);
    s.replaceChildren();
    for (const sh of scene.shapes) {
      let e;
      const id = sh.id ? { id: sh.id } : {};
      if (sh.type === 'line') {
        const pts = [];
        for (let i = 0; i < sh.points.length; i += 2) pts.push(sh.points[i] + ',' + (-sh.points[i + 1]));
        e = svg('polyline', Object.assign({ points: pts.join(' '), fill: 'none', stroke: sh.color || '#333',
          'stroke-width': sh.width || 0.1, 'stroke-linecap': 'round', 'stroke-dasharray': sh.dash || '' }, id));
      } else if (sh.type === 'circle') {
        e = svg('circle', Object.assign({ cx: sh.x, cy: -sh.y, r: sh.r, fill: sh.color || '#333',
          stroke: sh.stroke || 'none', 'stroke-width': sh.strokeWidth || 0.05, 'stroke-dasharray': sh.dash || '' }, id));
      } else if (sh.type === 'text') {
        e = svg('text', Object.assign({ x: sh.x, y: -sh.y, 'font-size': sh.size || 0.6, fill: sh.color || '#333',
          'text-anchor': 'middle' }, id), sh.text);
      } else {
        continue;
      }
      for (const [k, v] of Object.entries(sh.data || {})) e.setAttribute('data-' + k, v);
      if (sh.title) e.appendChild(svg('title', {}, sh.title));
      s.appendChild(e);
    }
    drawTables(scene.tables || []);
  }
  // A view's tables: each with a filter (rows holding the text) and an export as CSV; a table
  // that names an action makes its rows clickable (the hospital's audit trail asks for a story).
  // Each table's frame is made once, so the filter being typed in is not replaced by the next snapshot.
  function csvCell(v) {
    const t = v == null ? '' : String(v);
    return /[",\n\r]/.test(t) ? '"' + t.replace(/"/g, '""') + '"' : t;
  }
  function drawTables(tables) {
    const ids = new Set(tables.map((tb, i) => 'tw-' + (tb.id || i)));
    for (const box of [$('view-tables'), $('view-side-tables')]) for (const w of [...box.children]) if (!ids.has(w.id)) w.remove();
    tables.forEach((tb, i) => {
      const wid = 'tw-' + (tb.id || i);
      let w = $(wid);
      if (!w) {
        w = el('div', null, 'table-wrap');
        w.id = wid;
        const h = el('h3');
        const f = el('input', null, 'table-filter');
        f.type = 'search';
        f.placeholder = 'filter';
        f.addEventListener('input', () => drawTables(state.lastTables || []));
        const x = el('a', 'CSV', 'table-csv');
        x.download = (tb.id || 'table') + '.csv';
        const table = el('table');
        table.id = tb.id || '';
        w.append(h, f, x, table);
        (tb.wide ? $('view-tables') : $('view-side-tables')).appendChild(w);
      }
      w.querySelector('h3').textContent = tb.title;
      const q = w.querySelector('.table-filter').value.trim().toLowerCase();
      const keep = (r) => !q || r.some((c) => String(c).toLowerCase().includes(q));
      const table = w.querySelector('table');
      table.replaceChildren();
      const hr = el('tr');
      tb.columns.forEach((c) => hr.appendChild(el('th', c)));
      table.appendChild(hr);
      const rows = tb.rows.filter(keep);
      for (const r of rows) {
        const tr = el('tr');
        r.forEach((c) => tr.appendChild(el('td', c)));
        if (tb.click) {
          tr.className = 'pick';
          tr.dataset.key = r[tb.click.column];
          tr.addEventListener('click', () => viewAction(tb.click.action, { [tb.click.param]: r[tb.click.column] }));
        }
        table.appendChild(tr);
      }
      if (!rows.length) { const tr = el('tr'); const td = el('td', tb.rows.length ? 'none matches' : 'none', 'hint'); td.colSpan = tb.columns.length; tr.appendChild(td); table.appendChild(tr); }
      // The export: what the filter keeps, in the table's own CSV form if it gives one (full times, more columns).
      const cols = tb.csv ? tb.csv.columns : tb.columns;
      const all = tb.csv ? tb.csv.rows : tb.rows;
      const kept = all.filter((r, k) => keep(tb.rows[k] || r));
      w.querySelector('.table-csv').href = 'data:text/csv;charset=utf-8,' + encodeURIComponent(
        [cols].concat(kept).map((r) => r.map(csvCell).join(',')).join('\r\n') + '\r\n');
    });
    state.lastTables = tables;
  }
  function viewAction(action, params) {
    post('api/views/' + state.view.id + '/' + action, params, 'view-said');
  }

  // ---- bench ----------------------------------------------------------------------------------
  function loadBench() {
    fetch(url('api/bench')).then((r) => r.json()).then((files) => {
      const l = $('bench-list');
      l.replaceChildren();
      if (!files.length) l.appendChild(el('li', 'No bench report here: run bench/run, or start the console where bench/report is.', 'hint'));
      for (const f of files.filter((x) => x.endsWith('.md'))) {
        const li = el('li');
        const a = el('a', f);
        a.href = '#';
        a.addEventListener('click', (e) => { e.preventDefault(); openReport(f); });
        li.appendChild(a);
        l.appendChild(li);
      }
      if (files.includes('README.md') && !$('bench-page').childNodes.length) openReport('README.md');
    });
  }
  function inline(parent, text) {
    // **bold**, `code`, ![alt](img) and [text](link) in a line; the rest as text.
    const re = /(\*\*[^*]+\*\*|`[^`]+`|!\[[^\]]*\]\([^)]+\)|\[[^\]]+\]\([^)]+\))/g;
    let last = 0, m;
    while ((m = re.exec(text))) {
      parent.appendChild(document.createTextNode(text.slice(last, m.index)));
      const t = m[0];
      if (t.startsWith('**')) parent.appendChild(el('strong', t.slice(2, -2)));
      else if (t.startsWith('`')) parent.appendChild(el('code', t.slice(1, -1)));
      else if (t.startsWith('![')) {
        const src = t.slice(t.indexOf('(') + 1, -1);
        const img = el('img');
        img.alt = t.slice(2, t.indexOf(']'));
        if (/^[A-Za-z0-9._-]+\.(png|svg)$/.test(src)) img.src = url('api/bench/' + src);
        parent.appendChild(img);
      } else {
        const href = t.slice(t.indexOf('(') + 1, -1);
        const a = el('a', t.slice(1, t.indexOf(']')));
        if (/^[A-Za-z0-9._-]+\.md$/.test(href)) { a.href = '#'; a.addEventListener('click', (e) => { e.preventDefault(); openReport(href); }); }
        parent.appendChild(a);
      }
      last = m.index + t.length;
    }
    parent.appendChild(document.createTextNode(text.slice(last)));
    return parent;
  }
  function openReport(name) {
    fetch(url('api/bench/' + name)).then((r) => r.text()).then((md) => {
      const page = $('bench-page');
      page.replaceChildren();
      const lines = md.split('\n');
      for (let i = 0; i < lines.length; i++) {
        const line = lines[i];
        if (line.startsWith('```')) {
          const code = [];
          for (i++; i < lines.length && !lines[i].startsWith('```'); i++) code.push(lines[i]);
          page.appendChild(el('pre', code.join('\n')));
        } else if (/^#{1,4} /.test(line)) {
          page.appendChild(inline(el('h' + (line.indexOf(' ') + 1)), line.replace(/^#+ /, '')));
        } else if (line.startsWith('|')) {
          const table = el('table');
          for (; i < lines.length && lines[i].startsWith('|'); i++) {
            if (/^\|[\s:|-]+\|$/.test(lines[i])) continue;
            const tr = el('tr');
            lines[i].slice(1, -1).split('|').forEach((c) => tr.appendChild(inline(el('td'), c.trim())));
            table.appendChild(tr);
          }
          i--;
          page.appendChild(table);
        } else if (/^\s*[-*] /.test(line)) {
          page.appendChild(inline(el('li'), line.replace(/^\s*[-*] /, '')));
        } else if (line.trim()) {
          page.appendChild(inline(el('p'), line));
        }
      }
    });
  }

  // ---- replay: a recording played back in the same views, with a time slider ------------------
  function loadRecordings() {
    fetch(url('api/recordings')).then((r) => r.json()).then((o) => {
      // Says a recording is under way; what an action said stays otherwise.
      if (o.recording) $('record-said').textContent = 'recording to ' + o.recording;
      const l = $('recordings');
      l.replaceChildren();
      if (!o.files.length) l.appendChild(el('li', 'None yet: Record above, or start the demo with --record FILE.', 'hint'));
      for (const f of o.files) {
        const li = el('li');
        const a = el('a', f.name);
        a.href = '#';
        a.dataset.recording = f.name;
        a.addEventListener('click', (e) => { e.preventDefault(); openRecording(f.name); });
        li.appendChild(a);
        li.appendChild(el('span', ' ' + Math.max(1, Math.round(f.bytes / 1024)) + ' KiB', 'hint'));
        l.appendChild(li);
      }
    });
  }
  function recordAction(what) {
    post('api/record/' + what, formParams($('record-form')), 'record-said').then(() => loadRecordings());
  }
  $('record-start').addEventListener('click', () => recordAction('start'));
  $('record-stop').addEventListener('click', () => recordAction('stop'));
  function openRecording(name) {
    fetch(url('api/recordings/' + name)).then((r) => r.text()).then((text) => {
      const events = text.split('\n').filter((l) => l.trim()).map((l) => JSON.parse(l));
      if (!events.length) { $('record-said').textContent = name + ' holds nothing yet'; return; }
      if (state.source) { state.source.close(); state.source = null; }
      $('status').textContent = 'replay';
      $('status').className = 'status down';
      // A view the recording has and this console has not (a recording of another run) gets a tab.
      for (const e of events) {
        if (e.topic.startsWith('view-') && !state.views.some((v) => 'view-' + v.id === e.topic)) {
          const v = { id: e.topic.slice(5), title: e.topic.slice(5), actions: [] };
          state.views.push(v);
          const b = el('button', v.title);
          b.dataset.tab = 'view';
          b.dataset.view = v.id;
          b.addEventListener('click', () => show('view', v));
          $('view-tabs').appendChild(b);
        }
      }
      const t0 = events[0].t, t1 = events[events.length - 1].t;
      state.replay = { name: name, events: events, t0: t0, t1: t1, at: t0 };
      // What acts on the live platform (start, kill, send, a view's forms) is put away while replaying.
      document.body.classList.add('replaying');
      $('replay-name').textContent = name;
      $('replay-slider').max = t1 - t0;
      $('replay-slider').value = 0;
      $('replay-bar').hidden = false;
      replayAt(t0);
    });
  }
  // Every tab drawn as it was at time T: the last event of each topic until then, the messages sniffed until then.
  function replayAt(T) {
    const r = state.replay;
    if (!r) return;
    r.at = T;
    const last = {};
    const sniffed = [];
    for (const e of r.events) {
      if (e.t > T) break;
      if (e.topic === 'sniff') sniffed.push(e.data); else last[e.topic] = e.data;
    }
    state.sniffed = sniffed.slice(-500);
    if (last.platform) { state.platform = last.platform; drawPlatform(); }
    if (last.safety) { state.safety = last.safety; drawSafety(); drawPlatform(); }
    drawMail(last.mail || []);
    drawDiagram();
    if (state.view && last['view-' + state.view.id]) drawScene(last['view-' + state.view.id]);
    $('replay-time').textContent = ((T - r.t0) / 1000).toFixed(1) + ' s of ' + ((r.t1 - r.t0) / 1000).toFixed(1) + ' s';
    $('replay-time').dataset.t = T;
  }
  $('replay-slider').addEventListener('input', () => { stopPlaying(); replayAt(state.replay.t0 + Number($('replay-slider').value)); });
  function stopPlaying() {
    if (state.playing) { clearInterval(state.playing); state.playing = null; $('replay-play').textContent = 'Play'; }
  }
  $('replay-play').addEventListener('click', () => {
    if (state.playing) { stopPlaying(); return; }
    $('replay-play').textContent = 'Pause';
    state.playing = setInterval(() => {
      const r = state.replay;
      const T = Math.min(r.t1, r.at + 100);
      $('replay-slider').value = T - r.t0;
      replayAt(T);
      if (T >= r.t1) stopPlaying();
    }, 100);
  });
  $('replay-live').addEventListener('click', () => {
    stopPlaying();
    state.replay = null;
    document.body.classList.remove('replaying');
    $('replay-bar').hidden = true;
    connect(true);
  });

  loadViews();
})();
