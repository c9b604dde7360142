/**
 * What an <oceano-view> shows while it has no live picture: the page's poster before the
 * first frame, the last frame as a still image while its context is given back, and, for
 * reveal="interaction", the button that starts it. It lies over the canvas's place and is
 * taken away once the live picture is complete.
 */
export class FigureCover {
  private poster: HTMLImageElement | null = null;
  private still: HTMLCanvasElement | null = null;
  private revealButton: HTMLButtonElement | null = null;

  constructor(
    private readonly container: HTMLElement,
    private readonly alt: string,
  ) {}

  showPoster(url: string): void {
    const poster = (this.poster ??= this.layer(document.createElement('img'), 'oceano-poster'));
    poster.alt = this.alt;
    // A poster that cannot be had leaves the figure's plain background, not a broken-image icon.
    poster.addEventListener('error', () => poster.remove(), { once: true });
    poster.src = url;
  }

  /** A real <button> in the middle of the figure: reachable with Tab, started with Enter or Space. */
  showRevealButton(label: string, onActivate: () => void): void {
    const button = document.createElement('button');
    button.type = 'button';
    button.className = 'oceano-reveal';
    button.textContent = '▶';
    button.setAttribute('aria-label', label);
    button.title = label;
    button.addEventListener('click', () => {
      this.removeRevealButton();
      onActivate();
    });
    this.container.appendChild(button);
    this.revealButton = button;
  }

  /** Keeps the last live frame in place: a copy made while the WebGL canvas still holds it. */
  showStill(source: HTMLCanvasElement): void {
    const still = document.createElement('canvas');
    still.width = source.width;
    still.height = source.height;
    still.getContext('2d')?.drawImage(source, 0, 0);
    still.setAttribute('role', 'img');
    still.setAttribute('aria-label', this.alt);
    this.still?.remove();
    this.still = this.layer(still, 'oceano-still');
  }

  get hasStill(): boolean {
    return this.still !== null;
  }

  /** The live picture is complete: the poster and the still give way to it. */
  uncover(): void {
    this.poster?.remove();
    this.poster = null;
    this.still?.remove();
    this.still = null;
  }

  dispose(): void {
    this.uncover();
    this.removeRevealButton();
  }

  private removeRevealButton(): void {
    this.revealButton?.remove();
    this.revealButton = null;
  }

  private layer<T extends HTMLElement>(element: T, className: string): T {
    element.className = `oceano-cover ${className}`;
    this.container.appendChild(element);
    return element;
  }
}
