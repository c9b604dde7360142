/**
 * The small play/pause button over the canvas: the one control of an embedded view, and
 * the visible way to start a view that opened paused (reduced motion). A real <button>,
 * so it is reachable with Tab and works with Enter and Space.
 */
export class PlayButton {
  readonly element: HTMLButtonElement;

  constructor(
    container: HTMLElement,
    private readonly labels: { play: string; pause: string },
    onToggle: () => void,
  ) {
    this.element = document.createElement('button');
    this.element.type = 'button';
    this.element.className = 'oceano-play';
    this.element.addEventListener('click', onToggle);
    container.appendChild(this.element);
  }

  /**
   * Shows the action the button will take: "Play" while paused, "Pause" while playing. The
   * label says it all, so no aria-pressed: a toggle state on top of a changing label
   * would read as "Pause, pressed" (WAI-ARIA Authoring Practices, button pattern).
   */
  sync(playing: boolean): void {
    const label = playing ? this.labels.pause : this.labels.play;
    this.element.textContent = playing ? '❚❚' : '▶';
    this.element.setAttribute('aria-label', label);
    this.element.title = label;
  }

  dispose(): void {
    this.element.remove();
  }
}
