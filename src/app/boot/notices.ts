/** A web address inside a message: shown as a link of its own, selectable in one click. */
const URL_PATTERN = /https?:\/\/\S+/g;

/**
 * Readable messages for the user, shown over the canvas: never only in the console. Long
 * text wraps inside its notice (a share link is one long word), and the list scrolls when
 * it is taller than the view, so a small figure can still show every notice.
 */
export class Notices {
  private readonly list: HTMLElement;

  constructor(
    container: HTMLElement,
    private readonly dismissLabel: string,
  ) {
    this.list = document.createElement('div');
    this.list.className = 'oceano-notices';
    this.list.setAttribute('role', 'status');
    this.list.setAttribute('aria-live', 'polite');
    container.appendChild(this.list);
  }

  /** Shows a message; the returned element can be passed to `remove` when the condition ends. */
  show(message: string, level: 'warning' | 'error' = 'warning'): HTMLElement {
    const item = document.createElement('div');
    item.className = `oceano-notice oceano-notice-${level}`;
    const text = document.createElement('span');
    text.className = 'oceano-notice-text';
    text.append(...withLinks(message));
    const close = document.createElement('button');
    close.type = 'button';
    close.textContent = '×';
    close.setAttribute('aria-label', this.dismissLabel);
    close.addEventListener('click', () => item.remove());
    item.append(text, close);
    this.list.appendChild(item);
    return item;
  }

  remove(item: HTMLElement): void {
    item.remove();
  }

  messages(): string[] {
    return Array.from(this.list.querySelectorAll('.oceano-notice-text'), (el) => el.textContent ?? '');
  }

  dispose(): void {
    this.list.remove();
  }
}

/** The message as text nodes, with each web address in a span that one click selects whole (to copy where the clipboard is refused). */
function withLinks(message: string): Node[] {
  const nodes: Node[] = [];
  let last = 0;
  for (const match of message.matchAll(URL_PATTERN)) {
    const index = match.index ?? 0;
    if (index > last) nodes.push(document.createTextNode(message.slice(last, index)));
    // Not an <a>: a click meant to select the link must not navigate away from the view.
    const link = document.createElement('span');
    link.className = 'oceano-notice-link';
    link.textContent = match[0];
    nodes.push(link);
    last = index + match[0].length;
  }
  if (last < message.length) nodes.push(document.createTextNode(message.slice(last)));
  return nodes;
}
