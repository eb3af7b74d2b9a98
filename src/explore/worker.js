// The explorer's figure requests, made on a thread of their own: a
// request made from the page's thread during a drag leaves only once the
// frame after the pointer event is drawn, and its reply is parsed there;
// here it leaves at once and is parsed before the page is told. A
// message { id, url } asks for a figure, { id, abort: true } gives it up;
// the reply is { id, reply } (the figure's JSON), { id, failed } (a
// refusal's text), or { id, error } ('abort' when given up), with the
// request's resource timing as absolute times (ms since the epoch).
'use strict';
const asked = new Map();
const timing = (url) => {
  const entry = performance.getEntriesByName(url).pop();
  performance.clearResourceTimings();
  if (!entry) return null;
  return ['startTime', 'requestStart', 'responseStart', 'responseEnd'].map((k) => performance.timeOrigin + entry[k]);
};
self.onmessage = (ev) => {
  const { id, url, abort } = ev.data;
  if (abort) {
    const ctl = asked.get(id);
    if (ctl) ctl.abort();
    return;
  }
  const ctl = new AbortController();
  asked.set(id, ctl);
  fetch(url, { signal: ctl.signal })
    .then(async (r) => {
      if (!r.ok) return { id, failed: await r.text() };
      const reply = await r.json();
      return { id, reply, net: timing(url) };
    })
    .catch((e) => ({ id, error: e.name === 'AbortError' ? 'abort' : e.message }))
    .then((message) => {
      asked.delete(id);
      self.postMessage(message);
    });
};
