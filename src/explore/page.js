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

  // The figure: asked for once at a time; the newest state waits while
  // one is drawn, and a request slower than SLOW_MS is given up for it.
  let inflight = null;
  let waiting = false;
  let metadata = null;
  // Per figure asked for by a drag or a key: ms from the event to the
  // reply read, to the figure in the page, and to the next frame drawn.
  const timings = [];
  const phases = [];
  window.explorer = { timings, phases, state, metadata: () => metadata, ready: false, requests: 0, drawn: 0, abandoned: 0 };
  // A promise of the page settled with at least `n` figures drawn (for a
  // driver, which then need not poll).
  const waiters = [];
  const settle = () => {
    for (const w of waiters.splice(0)) {
      if (window.explorer.ready && window.explorer.drawn >= w.n) w.resolve(true);
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
  const draw = (started) => {
    const request = ask(new URL('/figure?' + figureQuery().toString(), location.href).href);
    inflight = { request, started: performance.now() };
    waiting = false;
    window.explorer.requests += 1;
    request.answer
      .then((m) => {
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
        // Values the figure refuses (a rod too short): the reason shown,
        // the last figure kept.
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
        requestAnimationFrame(() => {
          if (started === undefined) return;
          const framed = performance.now();
          timings.push(framed - started);
          // The network's part, from the worker's resource timing: fetch
          // called, the request sent, the reply's first and last bytes.
          const net = (m.net || [NaN, NaN, NaN, NaN]).map((t) => t - performance.timeOrigin - started);
          phases.push([replied - started, shown - started, framed - started, ...net]);
        });
      })
      .finally(() => {
        if (inflight && inflight.request === request) inflight = null;
        if (waiting) draw(waitingSince);
        else if (!inflight) {
          if (addressTimer !== null) writeAddress();
          window.explorer.ready = true;
          settle();
        }
      });
  };
  // The address and the download links follow the state: written at
  // most every ADDRESS_MS while it changes, and at once when the page
  // settles, after the figure's request has left. Chromium ignores a
  // page's history updates beyond 200 in 10 s (a drag at 60 Hz makes 600
  // requests in that time).
  const ADDRESS_MS = 100;
  let addressTimer = null;
  const writeAddress = () => {
    clearTimeout(addressTimer);
    addressTimer = null;
    history.replaceState(null, '', '?' + pageQuery().toString());
    links();
  };
  let waitingSince;
  const update = (started) => {
    window.explorer.ready = false;
    if (inflight && performance.now() - inflight.started > SLOW_MS) {
      inflight.request.abort();
      inflight = null;
      window.explorer.abandoned += 1;
    }
    if (inflight) {
      waiting = true;
      waitingSince = started;
    } else {
      draw(started);
    }
    if (addressTimer === null) addressTimer = setTimeout(writeAddress, ADDRESS_MS);
  };

  // Turning the crank: B dragged (mouse, pen, touch) or the arrow keys.
  const round = (x) => Math.round(x * 10) / 10;
  const setAngle = (deg, started) => {
    state.angle = String(round(((deg % 360) + 360) % 360));
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
  stage.addEventListener('pointermove', (ev) => {
    if (dragging === null || !metadata) return;
    const p = pagePoint(ev);
    if (!p) return;
    const w = pageToWorld(p, panelNamed(dragging).page_from_world);
    setAngle((Math.atan2(w.y, w.x) * 180) / Math.PI, performance.now());
  });
  const stop = () => {
    dragging = null;
    stage.classList.remove('dragging');
  };
  stage.addEventListener('pointerup', stop);
  stage.addEventListener('pointercancel', stop);
  stage.addEventListener('keydown', (ev) => {
    const turn = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1 }[ev.key];
    if (!turn || !figures.get(state.name).angle) return;
    ev.preventDefault();
    setAngle(Number(state.angle) + turn * (ev.shiftKey ? 0.1 : 1), performance.now());
  });

  form.addEventListener('input', () => {
    fromControls();
    toControls();
    update(performance.now());
  });
  form.addEventListener('submit', (ev) => ev.preventDefault());
  fromAddress();
  toControls();
  update(undefined);
})();
