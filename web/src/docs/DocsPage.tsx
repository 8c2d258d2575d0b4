/**
 * The docs page: the parameter reference (from the registry, like the panel), presets, share
 * links, embedding, the npm package, export and the command line (from the CLI's generated reference). All text
 * is rendered as text.
 */
import { useEffect } from 'react';
import { CliSection } from './CliSection';
import { Contents, ParameterSection, PresetSection, Section } from './DocsParts';
import { EmbeddingSection } from './EmbeddingSection';
import { LibrarySection } from './LibrarySection';
import type { DocsModel } from './model';

interface Props {
  model: DocsModel;
  version: string;
  /** This page's URL: the examples use absolute URLs next to it. */
  pageHref: string;
}

/** The documentation page. */
export function DocsPage({ model, version, pageHref }: Props) {
  // The target of a deep link (#embedding, #group-...) exists only once rendered.
  useEffect(() => {
    const id = decodeURIComponent(window.location.hash.slice(1));
    if (id) document.getElementById(id)?.scrollIntoView();
  }, []);
  return (
    <div className="docs">
      <header className="docs-header">
        <h1>Sylva documentation</h1>
        <span className="docs-version">core {version}</span>
        <a href="index.html" className="docs-back" data-testid="docs-back">
          Open the app
        </a>
      </header>

      <Contents model={model} />

      <main className="docs-main">
        <ParameterSection model={model} />
        <PresetSection model={model} />

        <Section id="share" title="Share links">
          <p>
            The app&apos;s address always holds the current tree: <code>?v=1</code> followed by the
            parameters that differ from their defaults (<code>id=value</code>, ids from the
            reference above) and, in growth mode, the volume primitives as <code>vol=</code>.
            Opening the link reproduces the same tree (the same content hash). Values outside their
            range or of the wrong type are ignored with a message.
          </p>
        </Section>

        <EmbeddingSection pageHref={pageHref} />
        <LibrarySection />

        <Section id="export" title="Export">
          <p>
            The app&apos;s <strong>Export</strong> menu saves the current tree:
          </p>
          <ul>
            <li>
              <strong>PNG screenshot</strong>: the current view at the size of the canvas.
            </li>
            <li>
              <strong>Save preset JSON</strong>: <code>{'{"sylva":1,"params":{...}}'}</code> with
              every parameter value. <strong>Load preset JSON</strong> reads such a file with the
              same validation as a share link; a file with an invalid value is refused with a
              message and the current tree stays.
            </li>
            <li>
              <strong>GLB for engines</strong> (glTF 2.0 binary: bark and instanced leaves, PBR
              materials, embedded textures, wind attributes): for three.js, Unity and Unreal.
            </li>
            <li>
              <strong>GLB for Blender and other editors</strong>: the same, with the leaves merged
              into one mesh (their tint and wind kept as vertex attributes), so an editor imports
              one object instead of one per leaf.
            </li>
            <li>
              <strong>GLB for Godot and strict importers</strong>: leaves merged, normals and
              tangents as plain floats, no glTF extension required (a larger file).
            </li>
            <li>
              <strong>OBJ + MTL + textures</strong> (one compressed zip; leaves baked into the
              mesh). All three are written by the core&apos;s exporters in a separate worker (the
              view stays responsive), the same bytes as <code>sylva generate --out</code> (
              <code>--leaves baked</code> for the editors&apos; GLB, <code>--strict</code> for the
              strict one).
            </li>
            <li>
              <strong>LODs + impostor</strong> (a zip of four GLBs: LOD0, LOD1, LOD2 and the
              impostor, crossed quads on the atlas the LOD view bakes in the page, with the atlas
              layout and the screen sizes in <code>extras</code>); <em>strict</em> writes the levels
              with no glTF extension. docs/formats.md (LOD zip) says how to use them in Unity,
              Unreal, Godot and Blender.
            </li>
          </ul>
        </Section>

        <Section id="cli" title="Command line">
          <CliSection />
        </Section>
      </main>
    </div>
  );
}
