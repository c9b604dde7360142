import type { Translator } from '../language/i18n';

/** What stands between opening the page and a finished view, in the order it happens. */
export const LOADING_STEPS = ['sky', 'firstFrame', 'boat'] as const;
export type LoadingStep = (typeof LOADING_STEPS)[number];

/**
 * The loading indicator: the three steps, each pending, under way or done, from the first
 * paint until the boat is in the picture. The page's HTML carries a plain one so that even
 * the seconds before the script arrives are not a blank rectangle; this adopts it.
 */
export class LoadingProgress {
  private readonly element: HTMLElement;
  private readonly bar: HTMLProgressElement;
  private readonly items = new Map<LoadingStep, HTMLLIElement>();

  constructor(
    container: HTMLElement,
    tr: Translator,
    private readonly onProgress: (fraction: number) => void = () => {},
  ) {
    this.element = container.querySelector<HTMLElement>(':scope > .oceano-loading') ?? document.createElement('div');
    this.element.className = 'oceano-loading';
    this.element.setAttribute('role', 'status');
    this.element.replaceChildren();
    const title = document.createElement('span');
    title.textContent = tr.ui('loadingTitle');
    this.bar = document.createElement('progress');
    this.bar.max = LOADING_STEPS.length;
    this.bar.setAttribute('aria-hidden', 'true');
    const list = document.createElement('ol');
    for (const step of LOADING_STEPS) {
      const item = document.createElement('li');
      item.dataset.step = step;
      item.dataset.state = 'pending';
      item.textContent = tr.ui(`loading_${step}`);
      list.appendChild(item);
      this.items.set(step, item);
    }
    this.element.append(title, this.bar, list);
    container.appendChild(this.element);
    this.begin('sky');
  }

  /** Marks the steps before `step` done and `step` under way. */
  begin(step: LoadingStep): void {
    const index = LOADING_STEPS.indexOf(step);
    LOADING_STEPS.forEach((s, i) => (this.items.get(s)!.dataset.state = i < index ? 'done' : i === index ? 'active' : 'pending'));
    this.bar.value = index;
    this.onProgress(index / LOADING_STEPS.length);
  }

  /**
   * Resolves after the browser has painted the indicator's current state. The steps that
   * follow (shader compilation, the first draw) hold the main thread for seconds on a
   * software GPU, and without this pause the page would show nothing of them. A hidden tab
   * paints nothing and runs no animation frames, so a timer stands in for it there.
   */
  painted(): Promise<void> {
    return new Promise((resolve) => {
      const fallback = setTimeout(resolve, 100);
      requestAnimationFrame(() => setTimeout(() => (clearTimeout(fallback), resolve()), 0));
    });
  }

  finish(): void {
    if (this.element.isConnected) this.onProgress(1);
    this.element.remove();
  }
}
