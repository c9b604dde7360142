/** One MathML equation, displayed as a block: browsers draw it without a library. */
export const m = (body: string) => `<math display="block">${body}</math>`;
