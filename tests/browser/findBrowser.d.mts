export declare const SYSTEM_BROWSERS: string[];
export declare function locateBrowser(): Promise<string | undefined>;
export declare const NO_BROWSER_MESSAGE: string;
