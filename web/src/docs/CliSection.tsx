/**
 * The docs page's Command line section, rendered from the generated reference (`cli.ts`): every
 * command with its synopsis, description, options and examples. All text is rendered as text.
 */
import { CLI_REFERENCE, codeSpans, synopsisParts, type CliCommand } from './cli';

/** Help text with its `backtick` spans as code. */
function Help({ text }: { text: string }) {
  return (
    <>
      {codeSpans(text).map((part, i) =>
        part.code ? <code key={i}>{part.text}</code> : <span key={i}>{part.text}</span>,
      )}
    </>
  );
}

function Command({ command }: { command: CliCommand }) {
  return (
    <section className="docs-cli-command" id={`cli-${command.name}`} data-command={command.name}>
      <h3>
        <code>sylva {command.name}</code>
      </h3>
      <p className="docs-code docs-synopsis">
        <code>
          {synopsisParts(command.synopsis).map((part, i) => (
            <span key={i}>
              {i > 0 && ' '}
              <span className="docs-synopsis-part">{part}</span>
            </span>
          ))}
        </code>
      </p>
      <p>
        <Help text={`${command.about}.`} /> {command.details && <Help text={command.details} />}
      </p>
      {command.options.length > 0 && (
        <table className="docs-cli-options">
          <thead>
            <tr>
              <th scope="col">Option</th>
              <th scope="col">What it does</th>
            </tr>
          </thead>
          <tbody>
            {command.options.map((option) => (
              <tr key={option.flag}>
                <td>
                  <code>{option.flag}</code>
                </td>
                <td>
                  <Help text={option.help} />
                  {option.default !== null && ` (default: ${option.default})`}
                </td>
              </tr>
            ))}
          </tbody>
        </table>
      )}
      <p className="docs-cli-label">Examples</p>
      <pre className="docs-code docs-example">
        <code>{command.examples.join('\n')}</code>
      </pre>
    </section>
  );
}

/** The section's content: the overview, then every command. */
export function CliSection() {
  return (
    <>
      <p>
        <Help text={`${CLI_REFERENCE.about}.`} />
      </p>
      <p>
        <Help text={CLI_REFERENCE.details} />
      </p>
      <p>
        <code>sylva help</code> and <code>sylva COMMAND --help</code> print the same in a terminal.
      </p>
      <div data-testid="docs-cli-commands">
        {CLI_REFERENCE.commands.map((command) => (
          <Command key={command.name} command={command} />
        ))}
      </div>
    </>
  );
}
