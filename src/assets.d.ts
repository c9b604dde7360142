/** Vite's `?inline` import: the file's text (CSS here), bundled into the script. */
declare module '*.css?inline' {
  const text: string;
  export default text;
}
