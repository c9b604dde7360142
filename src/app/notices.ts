/** Readable messages for the user, shown over the canvas: never only in the console. */
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
    text.textContent = message;
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
    return Array.from(this.list.querySelectorAll('.oceano-notice span'), (el) => el.textContent ?? '');
  }

  dispose(): void {
    this.list.remove();
  }
}
