// The browser harness lives in scripts/ because the bench and screenshot scripts drive the
// same built app; scripts never import from tests/.
export * from '../../scripts/browserHarness';
