import { locateBrowser, NO_BROWSER_MESSAGE } from '../../scripts/findBrowser.mjs';

/** The browser the tests drive; scripts/findBrowser.mjs says where it is looked for. */
export async function findBrowser(): Promise<string> {
  const found = await locateBrowser();
  if (!found) throw new Error(NO_BROWSER_MESSAGE);
  return found;
}
