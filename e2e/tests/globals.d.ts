/** The app's debug hook, as seen from e2e page scripts. */
interface Window {
  __sylva?: { panic(): void };
}
