(() => {
  'use strict';
  const data = JSON.parse(document.getElementById('explore-data').textContent);
  const figures = new Map(data.figures.map((f) => [f.name, f]));
  const $ = (id) => document.getElementById(id);
  const stage = $('stage');
  const form = $('controls');
  const SLOW_MS = 250;
  const NUMBERS = ['crank', 'rod', 'offset', 'angle', 'speed'];
  const CHOICES = ['notation', 'style', 'font', 'mirror'];

  // The state: what the address holds.
  const state = {};
  const fromAddress = () => {
    const q = new URLSearchParams(location.search);
    const name = q.get('name');
    state.name = figures.has(name) ? name : data.initial;
    const f = figures.get(state.name);
    for (const k of ['crank', 'rod', 'offset', 'angle']) {
      state[k] = q.has(k) ? q.get(k) : String(f.defaults[k]);
    }
    state.speedUnit = q.has('omega') ? 'omega' : 'rpm';
    state.speed = q.get(state.speedUnit) || '';
    state.layers = q.has('layers') ? q.get('layers').split(',').filter(Boolean) : null;
    for (const k of CHOICES) state[k] = q.get(k) || '';
    state.large = q.get('large') === '1';
  };

  // The figure request: the options of `figure` the figure takes.
  const figureQuery = () => {
    const f = figures.get(state.name);
    const q = new URLSearchParams({ name: state.name });
    if (f.mechanism) for (const k of ['crank', 'rod', 'offset']) q.set(k, state[k]);
    if (f.angle) q.set('angle', state.angle);
    if (f.speed && state.speed !== '') q.set(state.speedUnit, state.speed);
    if (f.layers) q.set('layers', (state.layers || f.defaults.layers).join(','));
    for (const k of CHOICES) if (f[k] && state[k] !== '') q.set(k, state[k]);
    return q;
  };
  const pageQuery = () => {
    const q = figureQuery();
    if (state.large) q.set('large', '1');
    return q;
  };

  // The controls shown as the state says.
  const names = $('name');
  let group = null;
  for (const f of data.figures) {
    if (!group || group.label !== f.group) {
      group = document.createElement('optgroup');
      group.label = f.group;
      names.appendChild(group);
    }
    const o = document.createElement('option');
    o.value = f.name;
    o.textContent = f.name;
    group.appendChild(o);
  }
  const toControls = () => {
    const f = figures.get(state.name);
    names.value = state.name;
    for (const k of ['crank', 'rod', 'offset', 'angle']) {
      $(k).value = state[k];
      $(k).disabled = !f[k === 'angle' ? 'angle' : 'mechanism'];
    }
    $('speed').value = state.speed;
    $('speed').placeholder = 'the figure’s own';
    $('speed-unit').value = state.speedUnit;
    $('speed').disabled = $('speed-unit').disabled = !f.speed;
    $('layers').hidden = !f.layers;
    const layers = state.layers || f.defaults.layers;
    for (const box of form.querySelectorAll('input[name=layer]')) box.checked = layers.includes(box.value);
    for (const k of CHOICES) {
      $(k).value = state[k];
      $(k).disabled = !f[k];
    }
    $('large').checked = state.large;
    document.body.classList.toggle('large', state.large);
  };
  const fromControls = () => {
    const before = state.name;
    state.name = names.value;
    for (const k of NUMBERS) state[k] = $(k).value.trim();
    state.speedUnit = $('speed-unit').value;
    if (state.name !== before) {
      const f = figures.get(state.name);
      state.layers = null;
      if (f.angle !== figures.get(before).angle || !f.mechanism) state.angle = String(f.defaults.angle);
      if (!figures.get(before).mechanism) {
        for (const k of ['crank', 'rod', 'offset']) state[k] = String(f.defaults[k]);
      }
    } else if (figures.get(state.name).layers) {
      state.layers = [...form.querySelectorAll('input[name=layer]:checked')].map((b) => b.value);
    }
    for (const k of CHOICES) state[k] = $(k).value;
    state.large = $('large').checked;
  };

  // The values `analyze` prints, exact beside graphical.
  const ROWS = [
    ['position of the slider', 'position', null, 'length'],
    ['velocity of the slider', 'velocity', 'velocity', 'velocity'],
    ['acceleration of the slider', 'acceleration', 'acceleration', 'acceleration'],
    ['rod angle φ', 'rod_angle_deg', null, '°'],
    ['rod angular velocity', 'rod_angular_velocity', 'rod_angular_velocity', 'angular_velocity'],
    ['rod angular acceleration', 'rod_angular_acceleration', 'rod_angular_acceleration', 'angular_acceleration'],
  ];
  const show = (x) => (x === null || x === undefined ? '—' : Number(x).toPrecision(6).replace(/^-/, '\u2212'));
  const showValues = (a) => {
    const body = $('values').tBodies[0];
    body.textContent = '';
    $('values-section').hidden = !a;
    if (!a) return;
    for (const [label, exact, graphical, unit] of ROWS) {
      const tr = body.insertRow();
      const u = unit === '°' ? '°' : ' ' + (a.units ? a.units[unit] : '');
      tr.insertCell().textContent = label;
      const e = tr.insertCell();
      e.textContent = show(a.analytic[exact]) + u;
      e.dataset.value = a.analytic[exact];
      const g = tr.insertCell();
      g.textContent = graphical ? show(a.graphical[graphical]) + u : '';
      if (graphical) g.dataset.value = a.graphical[graphical];
    }
  };

  // The figure: the current state's asked for once at a time; the newest
  // state waits while one is drawn, and a request slower than SLOW_MS is
  // given up for it. A drag or a key also asks ahead for the poses it is
  // heading to (AHEAD at most outstanding), and the replies are kept
  // (KEPT at most), so that a figure already kept is drawn at once, in
  // the handler of the event that asks for it, within the frame the event
  // begins (Chromium delivers a pointer move at the start of a frame,
  // before its animation callbacks: a reply read later is shown a frame
  // later).
  const AHEAD = 3;
  const KEPT = 24;
  let inflight = null;
  let waiting = false;
  let metadata = null;
  // Per figure drawn for a drag or a key: ms from the event (its handler
  // called) to the reply read, to the figure in the page, and to the next
  // frame drawn; the network's part; the same to the frame from the
  // event's own time stamp; and where the figure came from (SOURCES).
  const timings = [];
  const phases = [];
  const SOURCES = ['asked', 'asked ahead', 'kept'];
  window.explorer = {
    timings, phases, state, metadata: () => metadata, ready: false,
    requests: 0, drawn: 0, abandoned: 0, ahead: 0, adopted: 0, kept: 0, sources: SOURCES,
  };
  // Whether the current state's figure is drawn (or refused) and no
  // request for it is outstanding; the page is `ready` once the address
  // holds that state too.
  let calm = false;
  // A promise of the figure settled with at least `n` figures drawn (for
  // a driver, which then need not poll).
  const waiters = [];
  const settle = () => {
    for (const w of waiters.splice(0)) {
      if (calm && window.explorer.drawn >= w.n) w.resolve(true);
      else waiters.push(w);
    }
  };
  window.explorer.settled = (n) => new Promise((resolve) => {
    waiters.push({ n, resolve });
    settle();
  });
  const describe = () => {
    const f = figures.get(state.name);
    let text = f.source + ' (' + f.name + ')';
    if (f.mechanism) text += ': crank r = ' + state.crank + ', rod l = ' + state.rod + ', offset e = ' + state.offset + ' ' + f.defaults.unit;
    if (f.angle) text += ', at θ = ' + state.angle + '°';
    if (f.layers) text += '; layers ' + (state.layers || f.defaults.layers).join(', ');
    return text + '.';
  };
  const links = () => {
    const q = figureQuery().toString();
    for (const format of ['svg', 'png', 'pdf', 'tikz']) $('download-' + format).href = '/download?format=' + format + '&' + q;
    const f = figures.get(state.name);
    const h = new URLSearchParams();
    if (f.mechanism) for (const k of ['crank', 'rod', 'offset']) h.set(k, state[k]);
    h.set('angle', f.angle ? state.angle : '45');
    if (f.speed && state.speed !== '') h.set(state.speedUnit, state.speed);
    $('download-handout').href = '/handout?' + h.toString();
  };
  // The figure requests are made by a worker (/worker.js), off this
  // thread: `ask` sends one and gives a promise of the worker's answer
  // and a way to give it up.
  const worker = new Worker('/worker.js');
  const answers = new Map();
  let asked = 0;
  worker.onmessage = (ev) => {
    const answer = answers.get(ev.data.id);
    answers.delete(ev.data.id);
    if (answer) answer(ev.data);
  };
  const ask = (url) => {
    const id = ++asked;
    const answer = new Promise((resolve) => answers.set(id, resolve));
    worker.postMessage({ id, url });
    return { answer, abort: () => worker.postMessage({ id, abort: true }) };
  };
  // The replies kept by their figure query (a figure depends on its query
  // alone), the oldest dropped first; and the requests outstanding by
  // their query, one each, asked ahead or for the current state.
  const kept = new Map();
  const asking = new Map();
  window.explorer.outstanding = () => asking.size;
  const keep = (key, m) => {
    kept.delete(key);
    kept.set(key, m);
    if (kept.size > KEPT) kept.delete(kept.keys().next().value);
  };
  // A request for the figure `key`, `ahead` until the current state takes it.
  const request = (key) => {
    const r = { ...ask(new URL('/figure?' + key, location.href).href), key, ahead: true };
    asking.set(key, r);
    r.answer.then((m) => {
      if (asking.get(key) === r) asking.delete(key);
      if (m.reply !== undefined) keep(key, m);
    });
    return r;
  };
  const abandon = (r) => {
    r.abort();
    if (asking.get(r.key) === r) asking.delete(r.key);
  };
  // The figure query of the current state turned to `degrees`.
  const queryAt = (degrees) => {
    const q = figureQuery();
    q.set('angle', angleText(degrees));
    return q.toString();
  };
  // The poses the crank is heading to, at the last move's step, asked
  // for ahead unless kept or asked; asks ahead no longer wanted given up.
  const askAhead = () => {
    const wanted = [];
    for (let k = 1; k <= AHEAD && motion !== 0; k++) wanted.push(queryAt(Number(state.angle) + k * motion));
    for (const r of [...asking.values()]) if (r.ahead && !wanted.includes(r.key)) abandon(r);
    for (const key of wanted) {
      if (kept.has(key) || asking.has(key)) continue;
      request(key);
      window.explorer.ahead += 1;
    }
  };
  // The figure of the reply `m` shown, for the event `started` (none when
  // the page opens), the figure from SOURCES[source].
  const present = (m, started, source) => {
    if (m.error !== undefined) {
      if (m.error !== 'abort') $('status').textContent = 'the explorer cannot be reached: ' + m.error;
      return;
    }
    if (m.failed !== undefined) {
      $('status').textContent = m.failed.replace(/^slider-crank explore: /, '');
      return;
    }
    const reply = m.reply;
    const replied = performance.now();
    // Values the figure refuses (a rod too short): the reason shown, the
    // last figure kept.
    if (reply.refused !== undefined) {
      $('status').textContent = reply.refused;
      return;
    }
    stage.innerHTML = reply.svg;
    const svg = stage.querySelector('svg');
    if (svg) {
      svg.setAttribute('role', 'img');
      svg.setAttribute('aria-label', describe());
    }
    const m2 = stage.querySelector('metadata');
    metadata = m2 ? JSON.parse(m2.textContent) : null;
    showValues(reply.analyze);
    $('status').textContent = '';
    window.explorer.drawn += 1;
    $('description').textContent = describe();
    stage.setAttribute('aria-valuenow', state.angle);
    stage.setAttribute('aria-valuetext', 'θ = ' + state.angle + '°');
    const shown = performance.now();
    if (started === undefined) return;
    requestAnimationFrame(() => {
      const framed = performance.now();
      const from = started.at;
      timings.push(framed - from);
      // The network's part, from the worker's resource timing: fetch
      // called, the request sent, the reply's first and last bytes
      // (before the event for a figure asked ahead; none for one kept).
      const net = (source === 2 ? [] : m.net || []).map((t) => t - performance.timeOrigin - from);
      while (net.length < 4) net.push(NaN);
      phases.push([source === 2 ? NaN : replied - from, shown - from, framed - from, ...net, framed - started.event, source]);
    });
  };
  // Done with the current state: the state that waited asked for, or the
  // page settled.
  const done = () => {
    if (waiting) draw(waitingSince);
    else if (!inflight) {
      calm = true;
      window.explorer.ready = addressTimer === null;
      settle();
    }
  };
  const draw = (started) => {
    const key = figureQuery().toString();
    waiting = false;
    if (kept.has(key)) {
      // Drawn now, superseding a figure asked for an older state.
      if (inflight) abandon(inflight.request);
      inflight = null;
      window.explorer.kept += 1;
      present(kept.get(key), started, 2);
      askAhead();
      return done();
    }
    const known = asking.get(key);
    const r = known || request(key);
    const source = known ? 1 : 0;
    if (known) window.explorer.adopted += 1;
    else window.explorer.requests += 1;
    r.ahead = false;
    inflight = { request: r, started: performance.now() };
    r.answer
      .then((m) => {
        if (!inflight || inflight.request !== r) return;
        present(m, started, source);
        askAhead();
      })
      .finally(() => {
        if (!inflight || inflight.request !== r) return;
        inflight = null;
        done();
      });
  };
  // The address and the download links follow the state: written at
  // most every ADDRESS_MS while it changes (Chromium ignores a page's
  // history updates beyond 200 in 10 s, and a drag at 60 Hz changes the
  // state 600 times in that time), and never in the handler of the event
  // that changed it, whose figure comes first (writing them takes about
  // 2 ms).
  const ADDRESS_MS = 100;
  let addressTimer = null;
  let addressWritten = -Infinity;
  const writeAddress = () => {
    addressTimer = null;
    addressWritten = performance.now();
    history.replaceState(null, '', '?' + pageQuery().toString());
    links();
    window.explorer.ready = calm;
    settle();
  };
  const addressFollows = () => {
    if (addressTimer !== null) return;
    addressTimer = setTimeout(writeAddress, Math.max(0, addressWritten + ADDRESS_MS - performance.now()));
  };
  let waitingSince;
  const update = (started) => {
    calm = false;
    window.explorer.ready = false;
    addressFollows();
    if (inflight && performance.now() - inflight.started > SLOW_MS) {
      abandon(inflight.request);
      inflight = null;
      window.explorer.abandoned += 1;
    }
    if (inflight && !kept.has(figureQuery().toString())) {
      waiting = true;
      waitingSince = started;
    } else {
      draw(started);
    }
  };

  // Turning the crank: B dragged (mouse, pen, touch) or the arrow keys.
  // The angle as the state holds it: in [0°, 360°], to 0.1°.
  const angleText = (deg) => String(Math.round((((deg % 360) + 360) % 360) * 10) / 10);
  // The last turn's step, degrees (0: none to go on).
  let motion = 0;
  // The angle of the kept figure nearest `deg` among those within
  // `within` degrees of it whose query is the current state's but for
  // the angle (and not refused); null if there is none.
  const keptNear = (deg, within) => {
    let best = null;
    let gap = within;
    for (const [key, m] of kept) {
      const a = new URLSearchParams(key).get('angle');
      const off = Math.abs(((Number(a) - deg + 540) % 360) - 180);
      if (off <= gap && m.reply && m.reply.refused === undefined && queryAt(a) === key) {
        best = a;
        gap = off;
      }
    }
    return best;
  };
  // The crank turned to `deg` for the event `started`: to the pose of a
  // figure kept within `within` degrees of it if there is one (a drag
  // reads the angle to half a pixel at B), else to `deg` to 0.1°.
  const setAngle = (deg, started, within = 0) => {
    const before = Number(state.angle);
    state.angle = (within > 0 && keptNear(deg, within)) || angleText(deg);
    motion = ((Number(state.angle) - before + 540) % 360) - 180;
    $('angle').value = state.angle;
    update(started);
  };
  // The panel (the mechanism, or its enlarged detail) under a page
  // point: its own page-from-world map; the detail, drawn last, first.
  const panelAt = (p) => {
    const panels = (metadata.panels || []).filter((q) => {
      const [x, y, w, h] = q.rect;
      return p.x >= x && p.x <= x + w && p.y >= y && p.y <= y + h;
    });
    return panels.length ? panels[panels.length - 1] : { id: null, page_from_world: metadata.page_from_world };
  };
  const panelNamed = (id) => (metadata.panels || []).find((q) => q.id === id) || { page_from_world: metadata.page_from_world };
  const pageToWorld = (p, map) => {
    const [a, b, c, d, e, f] = map;
    const det = a * d - b * c;
    const x = p.x - e, y = p.y - f;
    return { x: (d * x - c * y) / det, y: (a * y - b * x) / det };
  };
  const pagePoint = (ev) => {
    const svg = stage.querySelector('svg');
    const ctm = svg && svg.getScreenCTM();
    if (!ctm) return null;
    return new DOMPoint(ev.clientX, ev.clientY).matrixTransform(ctm.inverse());
  };
  // The panel whose B the pointer is on, if any.
  const grabbedPanel = (ev) => {
    if (!metadata || !metadata.points || !metadata.points.B || !metadata.page_from_world) return null;
    const p = pagePoint(ev);
    if (!p) return null;
    const panel = panelAt(p);
    const svg = stage.querySelector('svg');
    const [a, b, c, d, e, f] = panel.page_from_world;
    const [x, y] = metadata.points.B;
    const at = new DOMPoint(a * x + c * y + e, b * x + d * y + f).matrixTransform(svg.getScreenCTM());
    const reach = ev.pointerType === 'touch' ? 44 : 24;
    return Math.hypot(at.x - ev.clientX, at.y - ev.clientY) <= reach ? panel : null;
  };
  let dragging = null;
  stage.addEventListener('pointerdown', (ev) => {
    if (!figures.get(state.name).angle) return;
    const panel = grabbedPanel(ev);
    if (!panel) return;
    dragging = panel.id || 'page';
    stage.classList.add('dragging');
    stage.setPointerCapture(ev.pointerId);
    ev.preventDefault();
  });
  // Half a CSS pixel at B in the panel `map` draws, as an angle of the
  // crank (degrees): the pointer's own reach (a mouse reports whole
  // pixels), within which a drag takes a figure already kept.
  const halfPixel = (map) => {
    const ctm = stage.querySelector('svg').getScreenCTM();
    const r = metadata.mechanism && metadata.mechanism.crank;
    const px = r * Math.hypot(map[0], map[1]) * Math.hypot(ctm.a, ctm.b);
    return px > 0 ? (0.5 / px) * (180 / Math.PI) : 0;
  };
  // The pointer's own angle, to which the crank is set when it is let go.
  let pointed = null;
  stage.addEventListener('pointermove', (ev) => {
    if (dragging === null || !metadata) return;
    const started = { at: performance.now(), event: ev.timeStamp };
    const p = pagePoint(ev);
    if (!p) return;
    const map = panelNamed(dragging).page_from_world;
    const w = pageToWorld(p, map);
    pointed = (Math.atan2(w.y, w.x) * 180) / Math.PI;
    setAngle(pointed, started, halfPixel(map));
  });
  const stop = (ev) => {
    if (dragging !== null && pointed !== null && state.angle !== angleText(pointed)) {
      setAngle(pointed, { at: performance.now(), event: ev.timeStamp });
    }
    pointed = null;
    dragging = null;
    stage.classList.remove('dragging');
  };
  stage.addEventListener('pointerup', stop);
  stage.addEventListener('pointercancel', stop);
  stage.addEventListener('keydown', (ev) => {
    const turn = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1 }[ev.key];
    if (!turn || !figures.get(state.name).angle) return;
    ev.preventDefault();
    setAngle(Number(state.angle) + turn * (ev.shiftKey ? 0.1 : 1), { at: performance.now(), event: ev.timeStamp });
  });

  form.addEventListener('input', (ev) => {
    motion = 0;
    fromControls();
    toControls();
    update({ at: performance.now(), event: ev.timeStamp });
  });
  form.addEventListener('submit', (ev) => ev.preventDefault());
  fromAddress();
  toControls();
  update(undefined);
})();
