/**
 * A critically damped spring that follows a moving target: what makes the boat float
 * rather than twitch with every ripple. Each step is the spring's exact solution over dt
 * for a target held constant during the step, so the result depends only on the sequence
 * of times (deterministic) and is stable for any dt. The state is then held within `band`
 * of the target, so an abrupt change (a parameter jump) can never leave the boat far
 * below or above the surface while the spring catches up.
 */
export interface FollowerState {
  value: number;
  velocity: number;
}

/**
 * @param omega natural angular frequency, 1/s (1 / response time)
 * @param band largest allowed |value − target|, same unit as value
 */
export function followStep(state: FollowerState, target: number, dt: number, omega: number, band: number): FollowerState {
  const error = state.value - target;
  const a = state.velocity + omega * error;
  const decay = Math.exp(-omega * dt);
  let value = target + (error + a * dt) * decay;
  let velocity = (state.velocity - omega * a * dt) * decay;
  if (value > target + band) {
    value = target + band;
    velocity = Math.min(velocity, 0);
  } else if (value < target - band) {
    value = target - band;
    velocity = Math.max(velocity, 0);
  }
  return { value, velocity };
}
