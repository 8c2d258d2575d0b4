/**
 * `sylva-trees/url`: the share-link format. Parameters, growth volumes and hand edits to and
 * from a query string (versioned, length-capped, hostile input reported as notices, never
 * thrown), and the number formatting and parsing it shares with preset files.
 */
export {
  buildSearch,
  decodeQuery,
  decodeVolumes,
  encodeParams,
  encodeVolumes,
  formatNumber,
  parseValue,
  shown,
  FORMAT_VERSION,
  MAX_QUERY_LENGTH,
  VOLUMES_KEY,
  type DecodeResult,
} from './codec';
export {
  decodeEdits,
  editsFitLink,
  encodeEdits,
  EDITS_KEY,
  MAX_EDITS_LINK_LENGTH,
} from './editsCodec';
