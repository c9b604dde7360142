import { paramDefs, type OceanParams } from '../../sim/params/params';

/** How fast a held key turns the boat, degrees per second. */
const TURN_RATE = 45;
/** How fast a held key changes the boat's speed, m/s per second. */
const ACCELERATION = 2;

const AHEAD = new Set(['KeyW', 'ArrowUp']);
const ASTERN = new Set(['KeyS', 'ArrowDown']);
const PORT = new Set(['KeyA', 'ArrowLeft']);
const STARBOARD = new Set(['KeyD', 'ArrowRight']);

/** `value` rounded to a multiple of `step`, written with no more decimals than the step has (0.1 → one). */
export function onStep(value: number, step: number): number {
  const decimals = Math.max(0, -Math.floor(Math.log10(step) + 1e-9));
  return Number((Math.round(value / step) * step).toFixed(decimals));
}

/**
 * Keyboard steering: W/↑ and S/↓ change the speed, A/← and D/→ turn to port and starboard,
 * for as long as they are held. The keys change the same parameters as the GUI
 * (boatSpeed, boatHeading), so the panel, the URL names and the API agree with them.
 * Keys typed into a form field (the GUI's number boxes) are left alone.
 */
export class BoatSteering {
  private readonly held = new Set<string>();
  /** Keys pressed since the last frame: a tap shorter than a frame still counts for one. */
  private readonly unapplied = new Set<string>();
  /** Keys let go of before a frame applied them, to drop after the next one does. */
  private readonly released = new Set<string>();
  /**
   * The unrounded values the keys have reached, and the rounded ones stored from them: the
   * parameters hold values on their GUI step (2.4, not 2.4335999999999984, which would
   * show up in links), while a frame's small change still adds up.
   */
  private exact: { speed: number; heading: number; stored: { speed: number; heading: number } } | null = null;

  constructor(
    private readonly target: Window | HTMLElement,
    private readonly setParams: (change: Partial<OceanParams>) => void,
    private readonly params: () => OceanParams,
  ) {
    target.addEventListener('keydown', this.onKeyDown);
    target.addEventListener('keyup', this.onKeyUp);
    target.addEventListener('blur', this.onBlur);
  }

  private readonly onKeyDown = (e: Event): void => {
    const event = e as KeyboardEvent;
    const element = event.target as HTMLElement | null;
    if (element && ['INPUT', 'TEXTAREA', 'SELECT'].includes(element.tagName)) return;
    if (![AHEAD, ASTERN, PORT, STARBOARD].some((keys) => keys.has(event.code))) return;
    event.preventDefault();
    if (!this.held.has(event.code)) this.unapplied.add(event.code);
    this.held.add(event.code);
    this.released.delete(event.code);
  };

  private readonly onKeyUp = (e: Event): void => {
    const event = e as KeyboardEvent;
    // Released before any frame applied it: let the next frame count it, then let go.
    if (this.unapplied.has(event.code)) this.released.add(event.code);
    else this.held.delete(event.code);
  };

  private readonly onBlur = (): void => {
    this.held.clear();
    this.unapplied.clear();
    this.released.clear();
  };

  private holding(keys: Set<string>): number {
    return [...keys].some((key) => this.held.has(key)) ? 1 : 0;
  }

  /** Applies the held keys, and the boatTurnRate parameter, over `seconds` of the frame loop's time. */
  apply(seconds: number): void {
    if (seconds <= 0) return;
    const turn = this.holding(STARBOARD) - this.holding(PORT);
    const throttle = this.holding(AHEAD) - this.holding(ASTERN);
    for (const key of this.released) this.held.delete(key);
    this.released.clear();
    this.unapplied.clear();
    const { boatHeading, boatSpeed, boatTurnRate } = this.params();
    if (turn === 0 && throttle === 0 && boatTurnRate === 0) return;
    // Start from the stored values whenever something else (GUI, API, URL) changed them.
    const stored = this.exact?.stored;
    if (!this.exact || stored?.speed !== boatSpeed || stored.heading !== boatHeading)
      this.exact = { speed: boatSpeed, heading: boatHeading, stored: { speed: boatSpeed, heading: boatHeading } };
    const exact = this.exact;
    // The boatTurnRate parameter is a rudder held over: it turns the boat as a key does.
    exact.heading = (((exact.heading + (turn * TURN_RATE + boatTurnRate) * seconds) % 360) + 360) % 360;
    const { min, max } = paramDefs.boatSpeed;
    exact.speed = Math.min(max, Math.max(min, exact.speed + throttle * ACCELERATION * seconds));
    exact.stored = {
      speed: onStep(exact.speed, paramDefs.boatSpeed.step),
      heading: onStep(exact.heading, paramDefs.boatHeading.step) % 360,
    };
    this.setParams({ boatHeading: exact.stored.heading, boatSpeed: exact.stored.speed });
  }

  dispose(): void {
    this.target.removeEventListener('keydown', this.onKeyDown);
    this.target.removeEventListener('keyup', this.onKeyUp);
    this.target.removeEventListener('blur', this.onBlur);
  }
}
