/** Vite's `?inline` import: the file's text (CSS here), bundled into the script. */
declare module '*.css?inline' {
  const text: string;
  export default text;
}
/** Vite's `?worker&url` import: the URL of the Worker script Vite bundles from the file. */
declare module '*?worker&url' {
  const url: string;
  export default url;
}
