// Reading Markdown the way GitHub renders it, for the README and docs tests (readme.test.mjs).

/** The anchor GitHub gives a heading: lower case, punctuation dropped, spaces as hyphens. */
export function githubSlug(heading) {
  return heading
    .toLowerCase()
    .replace(/[^\p{L}\p{N}\s_-]/gu, '')
    .replace(/\s/g, '-');
}

/** The targets of the inline links and images in `markdown`, outside code. */
export function links(markdown) {
  const text = markdown.replace(/```[\s\S]*?```/g, '').replace(/`[^`\n]*`/g, '');
  return [...text.matchAll(/!?\[[^\]]*\]\(([^)\s]+)\)/g)].map((m) => m[1]);
}

/** The first fenced code block of the `## title` section of `markdown` ('' when absent). */
export function sectionCode(markdown, title) {
  const start = markdown.indexOf(`\n## ${title}\n`);
  if (start < 0) return '';
  const rest = markdown.slice(start + title.length + 5);
  const section = rest.split(/\n## /)[0];
  const block = /```[a-z]*\n([\s\S]*?)```/.exec(section);
  return block ? block[1] : '';
}
