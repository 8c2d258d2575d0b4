/**
 * The forest's recipe in the share link: `forest=<count>:<seed>:<species>,<species>,…`, e.g.
 * `forest=16:7:quaking_aspen,fir,oak,cypress`. The count of unique trees is 1..64 (16 by
 * default), the seed a whole number below 2³², the species preset names. A hostile or broken
 * entry never stops the page: each part that does not parse falls back to its default and the
 * notices say what was wrong, in words.
 */

/** What the forest is made of. */
export interface ForestRecipe {
  /** Unique trees (1..`MAX_UNIQUE`). */
  count: number;
  seed: number;
  /** Preset names, in order: the species map's indices. */
  species: string[];
}

/** Default and largest number of unique trees. */
export const DEFAULT_UNIQUE = 16;
export const MAX_UNIQUE = 64;
/** Default seed. */
export const DEFAULT_FOREST_SEED = 1;
/** Longest entry read (a link's recipe is a few dozen characters). */
const MAX_ENTRY = 2000;
/** Most species in one forest. */
export const MAX_SPECIES = 16;

/** The recipe as link text. */
export function encodeRecipe(recipe: ForestRecipe): string {
  return `${recipe.count}:${recipe.seed}:${recipe.species.join(',')}`;
}

/**
 * The recipe in `text` (null: no entry, the defaults). `known`: the preset names there are;
 * `defaults`: the species when the entry names none that exist. Never throws.
 */
export function decodeRecipe(
  text: string | null,
  known: readonly string[],
  defaults: readonly string[],
): { recipe: ForestRecipe; notices: string[] } {
  const fallback: ForestRecipe = {
    count: DEFAULT_UNIQUE,
    seed: DEFAULT_FOREST_SEED,
    species: defaults.filter((s) => known.includes(s)),
  };
  if (fallback.species.length === 0 && known.length > 0) fallback.species = [known[0]!];
  if (text === null || text === '') return { recipe: fallback, notices: [] };
  if (text.length > MAX_ENTRY) {
    return {
      recipe: fallback,
      notices: [`forest recipe ignored: ${text.length} characters, at most ${MAX_ENTRY}`],
    };
  }
  const notices: string[] = [];
  const [countText = '', seedText = '', speciesText = '', ...rest] = text.split(':');
  if (rest.length > 0) notices.push('forest recipe: extra parts after the species ignored');
  const recipe = { ...fallback };
  const count = /^\d{1,3}$/.test(countText) ? Number(countText) : NaN;
  if (count >= 1 && count <= MAX_UNIQUE) recipe.count = count;
  else notices.push(`forest recipe: tree count "${clip(countText)}" is not 1..${MAX_UNIQUE}`);
  const seed = /^\d{1,10}$/.test(seedText) ? Number(seedText) : NaN;
  if (seed >= 0 && seed <= 0xffffffff) recipe.seed = seed;
  else notices.push(`forest recipe: seed "${clip(seedText)}" is not a whole number below 2^32`);
  const names = speciesText === '' ? [] : speciesText.split(',');
  const good = [...new Set(names.filter((n) => known.includes(n)))].slice(0, MAX_SPECIES);
  const bad = names.filter((n) => !known.includes(n));
  if (bad.length > 0) {
    notices.push(`forest recipe: unknown species ${bad.slice(0, 3).map(clip).join(', ')}`);
  }
  if (good.length > 0) recipe.species = good;
  else if (speciesText !== '') notices.push('forest recipe: no known species, the default mix');
  return { recipe, notices };
}

/** At most 40 characters of hostile text, for a notice. */
function clip(s: string): string {
  const t = s.replace(/[^\x20-\x7e]/g, '?');
  return t.length > 40 ? `${t.slice(0, 40)}…` : t;
}
