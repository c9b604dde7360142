/**
 * Starts the module Worker at `url`. A Worker's script must come from the page's own origin;
 * when it does not (the element loaded from a CDN that mirrors npm packages), a same-origin
 * stand-in made on the spot imports it, which a CDN's CORS headers allow.
 */
export function startModuleWorker(url: URL): Worker {
  if (url.origin === location.origin) return new Worker(url, { type: 'module' });
  const standIn = new Blob([`import ${JSON.stringify(url.href)};`], { type: 'text/javascript' });
  return new Worker(URL.createObjectURL(standIn), { type: 'module' });
}
