import { describe, expect, it } from 'vitest';
import { parseUrlState, parseVector3 } from '../../src/app/urlState';

describe('camera and target in the URL', () => {
  it('reads camera=x,y,z and target=x,y,z, including a position under the water', () => {
    const state = parseUrlState('?camera=0,-6,40&target=0,-6,-20');
    expect(state.camera).toEqual([0, -6, 40]);
    expect(state.target).toEqual([0, -6, -20]);
    expect(state.notices).toEqual([]);
  });

  it('leaves them null when absent and gives a notice for a malformed triple', () => {
    expect(parseUrlState('?t=3').camera).toBeNull();
    const bad = parseUrlState('?camera=1,2&target=a,b,c');
    expect(bad.camera).toBeNull();
    expect(bad.target).toBeNull();
    expect(bad.notices).toHaveLength(2);
    expect(bad.notices[0]).toMatch(/camera=1,2/);
  });

  it('rejects empty parts, non-finite and huge numbers', () => {
    expect(parseVector3('1,,2')).toBeNull();
    expect(parseVector3('1,Infinity,2')).toBeNull();
    expect(parseVector3('1,2e7,2')).toBeNull();
    expect(parseVector3(' 1, -2.5 ,3')).toEqual([1, -2.5, 3]);
  });
});
