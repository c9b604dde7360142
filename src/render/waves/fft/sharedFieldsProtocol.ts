/**
 * The CPU twin's fields over shared memory, with no message per frame (issue 12: one
 * postMessage round trip per frame cost about the whole 0.1 ms main-thread budget).
 *
 * One control block per sea (a "channel": a new sea, a new channel and new slot buffers of its
 * size), shared by the main thread and the Worker:
 *  - the main thread writes the time it wants (writeRequest: a sequence lock, no notify, so
 *    the Worker is not woken onto the main thread's core);
 *  - the Worker polls it on its own timer (readRequest), computes the fields into a slot
 *    (chooseWriteSlot: three slots, never the one the main thread reads, never the newest
 *    published one) and publishes that slot with its time (publish);
 *  - each frame the main thread takes the newest publication (takePublication) and adopts
 *    float64 views of that slot, no copy, marking it read until it adopts another.
 * Pure logic over Int32Array / Float64Array views (shared in the app; tests may use any
 * buffer: Atomics.load / store / add also work on unshared integer arrays).
 */

import type { CascadeFields } from '../../../sim/waves/fft/fftOcean';
import type { SeaState } from '../../../sim/waves/spectra/seaState';

/** The one message per sea (not per frame) that hands the Worker a channel: see sharedFieldsProtocol.ts. */
export interface ChannelMessage {
  kind: 'channel';
  sea: SeaState;
  generation: number;
  control: SharedArrayBuffer;
  slots: SharedArrayBuffer[];
}

/** Bytes of one slot: `cascades` cascades of two RGBA float64 fields of n × n texels (fieldsOn's layout). */
export function slotBytes(cascades: number, n: number): number {
  return cascades * 2 * 4 * n * n * Float64Array.BYTES_PER_ELEMENT;
}

/**
 * Float64 fields of `cascades` cascades of n × n texels, views of ONE buffer in packedFields'
 * layout (cascade by cascade, displacement then derivatives), so the Worker's copyFields
 * writes into them in place.
 */
export function fieldsOn(buffer: ArrayBufferLike, cascades: number, n: number): CascadeFields[] {
  const length = 4 * n * n;
  return Array.from({ length: cascades }, (_, c) => ({
    displacement: new Float64Array(buffer, 2 * c * length * 8, length),
    derivatives: new Float64Array(buffer, (2 * c + 1) * length * 8, length),
  }));
}

/** Int32 words of the control block. */
const REQUEST_SEQ = 0; // even: a request is complete; odd: being written.
const PUBLISHED = 1; // (count << 2) | slot of the newest publication; slot NONE before the first.
const READING = 2; // the slot whose views the main thread holds, NONE if none.
const GENERATION = 3; // the channel's sea generation, written once at creation.
const SLOT_GENERATION = 4; // 3 words: the generation each slot's fields were computed for.
const INT_WORDS = 8;
/** Float64 words after the ints: the requested time, then each slot's time. */
const REQUEST_TIME = 0;
const SLOT_TIME = 1;
const FLOAT_WORDS = 4;

export const SLOTS = 3;
const NONE = 3;

export interface SharedControl {
  readonly ints: Int32Array;
  readonly floats: Float64Array;
}

/** Bytes of a control block (ints then floats, float-aligned). */
export const CONTROL_BYTES = INT_WORDS * 4 + FLOAT_WORDS * 8;

/** Views on a control block; `initialise` (the creating side only) sets its empty state for `generation`. */
export function controlViews(buffer: ArrayBufferLike, generation?: number): SharedControl {
  const control = { ints: new Int32Array(buffer, 0, INT_WORDS), floats: new Float64Array(buffer, INT_WORDS * 4, FLOAT_WORDS) };
  if (generation !== undefined) {
    Atomics.store(control.ints, PUBLISHED, NONE);
    Atomics.store(control.ints, READING, NONE);
    for (let s = 0; s < SLOTS; s++) Atomics.store(control.ints, SLOT_GENERATION + s, -1);
    Atomics.store(control.ints, GENERATION, generation);
  }
  return control;
}

export function channelGeneration(control: SharedControl): number {
  return Atomics.load(control.ints, GENERATION);
}

/** Main thread: asks for the fields at `time` (the newest request replaces any older one). */
export function writeRequest(control: SharedControl, time: number): void {
  // Sequence lock: odd while the float is written, so a reader never takes a torn time.
  Atomics.add(control.ints, REQUEST_SEQ, 1);
  control.floats[REQUEST_TIME] = time;
  Atomics.add(control.ints, REQUEST_SEQ, 1);
}

/** Worker: the newest request if one newer than `seen` (a sequence number) is complete, else null. */
export function readRequest(control: SharedControl, seen: number): { seq: number; time: number } | null {
  const before = Atomics.load(control.ints, REQUEST_SEQ);
  if (before === seen || before % 2 !== 0) return null;
  const time = control.floats[REQUEST_TIME];
  return Atomics.load(control.ints, REQUEST_SEQ) === before ? { seq: before, time } : null;
}

/** Worker: a slot it may write: neither the one the main thread reads nor the newest published. */
export function chooseWriteSlot(control: SharedControl): number {
  const reading = Atomics.load(control.ints, READING);
  const published = Atomics.load(control.ints, PUBLISHED) & 3;
  for (let s = 0; s < SLOTS; s++) if (s !== reading && s !== published) return s;
  throw new Error('No free slot: the control block is corrupt.');
}

/** Worker: the fields in `slot` are complete, for `time` of `generation`; make them the newest. */
export function publish(control: SharedControl, slot: number, time: number, generation: number): void {
  control.floats[SLOT_TIME + slot] = time;
  Atomics.store(control.ints, SLOT_GENERATION + slot, generation);
  const count = (Atomics.load(control.ints, PUBLISHED) >>> 2) + 1;
  // The store is the release: everything written before it is visible to whoever loads it.
  Atomics.store(control.ints, PUBLISHED, ((count & 0x1fffffff) << 2) | slot);
}

export interface Publication {
  /** The PUBLISHED word taken (pass it back as `seen` next frame). */
  readonly word: number;
  readonly slot: number;
  readonly time: number;
  /** The slot marked read before this one (restore it with release if the fields are refused). */
  readonly previous: number;
}

/**
 * Main thread: the newest publication if it is not `seen`, with its slot now marked as read
 * (the Worker will not write it) — or null: nothing new, or a publication of another
 * generation (stale: refused, and the slot read stays as it was).
 */
export function takePublication(control: SharedControl, seen: number, generation: number): Publication | null {
  const { ints } = control;
  const previous = Atomics.load(ints, READING);
  for (;;) {
    const word = Atomics.load(ints, PUBLISHED);
    const slot = word & 3;
    if (word === seen || slot === NONE) return null;
    Atomics.store(ints, READING, slot);
    // The Worker may have chosen this slot to write after publishing a newer one and before
    // it saw the mark: then PUBLISHED has moved on since the load above. Try again.
    if (Atomics.load(ints, PUBLISHED) !== word) continue;
    if (Atomics.load(ints, SLOT_GENERATION + slot) !== generation) {
      Atomics.store(ints, READING, previous);
      return null;
    }
    return { word, slot, time: control.floats[SLOT_TIME + slot], previous };
  }
}

/** Main thread: the fields of a taken publication were not adopted; mark the slot held before as read again. */
export function release(control: SharedControl, publication: Publication): void {
  Atomics.store(control.ints, READING, publication.previous);
}
