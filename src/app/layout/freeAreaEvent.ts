/** The event a view's container receives when the free part of its canvas changes (freeArea.ts); detail: the Rect, CSS px from the canvas's top left. */
export const FREE_AREA_EVENT = 'oceano-free-area';
