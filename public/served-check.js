// Oceano's page opened from disk (file://): browsers refuse its JavaScript modules there,
// so nothing else would run and the page would stay blank. This classic script still
// runs, says in words what to do, and gives window.oceano a `ready` that rejects with the
// same reason, so a harness awaiting it fails instead of screenshotting a blank page.
// Plain ES5 in public/ (copied as is), because it must run without the build's modules.
(function () {
  if (location.protocol !== 'file:') return;
  var spanish = /^es\b/i.test(navigator.language || '');
  var text = spanish
    ? 'Oceano tiene que servirse por http(s): los navegadores no cargan sus módulos desde un archivo (file://). En la carpeta de index.html ejecuta: python3 -m http.server 8000 y abre http://localhost:8000/'
    : 'Oceano has to be served over http(s): browsers do not load its modules from a file (file://). In the folder holding index.html run: python3 -m http.server 8000 and open http://localhost:8000/';
  var page = document.getElementById('oceano-page') || document.body;
  // Nothing is loading: the words below take the loading indicator's place.
  var loading = page.querySelector('.oceano-loading');
  if (loading) loading.remove();
  var box = document.createElement('div');
  box.className = 'oceano-fatal';
  box.setAttribute('role', 'alert');
  box.textContent = text;
  // Styled here: the page's stylesheet, fetched in CORS mode, does not load from file:// either.
  document.body.style.background = '#0a2e45';
  box.style.color = '#e8f2f7';
  box.style.font = '18px/1.5 system-ui, sans-serif';
  box.style.padding = '24px';
  box.style.maxWidth = '44em';
  box.style.margin = '10vh auto';
  box.style.textAlign = 'center';
  page.appendChild(box);
  var ready = Promise.reject(new Error(text));
  ready.catch(function () {});
  window.oceano = { ready: ready };
})();
