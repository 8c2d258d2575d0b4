/**
 * The docs page's building blocks and its generated sections: the contents, the parameter
 * reference (from the registry, like the panel) and the presets.
 */
import type { ReactNode } from 'react';
import { CLI_REFERENCE } from './cli';
import type { DocsModel } from './model';

/** A code block (text only). */
export function Code({ children }: { children: string }) {
  return (
    <pre className="docs-code">
      <code>{children}</code>
    </pre>
  );
}

/** A top-level section with its anchor and heading. */
export function Section(props: { id: string; title: string; children: ReactNode }) {
  return (
    <section id={props.id} className="docs-section" data-testid={`docs-${props.id}`}>
      <h2>{props.title}</h2>
      {props.children}
    </section>
  );
}

/** A table with a header row of `columns`. */
export function DocsTable(props: {
  className: string;
  columns: string[];
  testId?: string;
  children: ReactNode;
}) {
  return (
    <table className={props.className} data-testid={props.testId}>
      <thead>
        <tr>
          {props.columns.map((column) => (
            <th key={column} scope="col">
              {column}
            </th>
          ))}
        </tr>
      </thead>
      <tbody>{props.children}</tbody>
    </table>
  );
}

/** The table of contents. */
export function Contents({ model }: { model: DocsModel }) {
  return (
    <nav className="docs-toc" aria-label="Contents">
      <ul>
        <li>
          <a href="#parameters">Parameters</a>
          <ul>
            {model.groups.map((group) => (
              <li key={group.anchor}>
                <a href={`#${group.anchor}`}>{group.name}</a>
              </li>
            ))}
          </ul>
        </li>
        <li>
          <a href="#presets">Presets</a>
        </li>
        <li>
          <a href="#share">Share links</a>
        </li>
        <li>
          <a href="#embedding">Embedding</a>
        </li>
        <li>
          <a href="#library">In your own three.js scene</a>
        </li>
        <li>
          <a href="#export">Export</a>
        </li>
        <li>
          <a href="#cli">Command line</a>
          <ul>
            {CLI_REFERENCE.commands.map((command) => (
              <li key={command.name}>
                <a href={`#cli-${command.name}`}>sylva {command.name}</a>
              </li>
            ))}
          </ul>
        </li>
      </ul>
    </nav>
  );
}

/** Every parameter, group by group, in the order of the panel. */
export function ParameterSection({ model }: { model: DocsModel }) {
  return (
    <Section id="parameters" title="Parameters">
      <p>
        All {model.count} parameters in {model.groups.length} groups, in the order of the panel.
        This reference is built from the core&apos;s parameter registry when the page loads, the
        same source as the panel, the share links and their validation. Booleans are 0 or 1, options
        are given by their number.
      </p>
      {model.groups.map((group) => (
        <section
          key={group.anchor}
          id={group.anchor}
          className="docs-group"
          data-group={group.name}
        >
          <h3>{group.name}</h3>
          <DocsTable
            className="docs-params"
            columns={['Parameter', 'Default', 'Range', 'Unit', 'Description']}
          >
            {group.params.map((p) => (
              <tr key={p.id} id={`param-${p.id}`} data-param-id={p.id}>
                <th scope="row">
                  <span className="docs-label">{p.label}</span>
                  <code className="docs-id" data-testid={`doc-id-${p.id}`}>
                    {p.id}
                  </code>
                  <span className="docs-kind">{p.kind}</span>
                </th>
                <td data-testid={`doc-default-${p.id}`}>{p.defaultText}</td>
                <td data-testid={`doc-range-${p.id}`}>{p.rangeText}</td>
                <td>{p.unit}</td>
                <td>{p.description}</td>
              </tr>
            ))}
          </DocsTable>
        </section>
      ))}
    </Section>
  );
}

/** The presets' names, labels and descriptions. */
export function PresetSection({ model }: { model: DocsModel }) {
  return (
    <Section id="presets" title="Presets">
      <p>
        A preset is a set of values over the defaults; the panel&apos;s preset menu, the
        <code> preset</code> attribute of <code>&lt;sylva-tree&gt;</code> and{' '}
        <code>sylva generate --preset</code> take these names.
      </p>
      <DocsTable className="docs-presets" columns={['Name', 'Label', 'Description']}>
        {model.presets.map((p) => (
          <tr key={p.name} data-preset={p.name}>
            <td>
              <code>{p.name}</code>
            </td>
            <td>{p.label}</td>
            <td>{p.description}</td>
          </tr>
        ))}
      </DocsTable>
    </Section>
  );
}
