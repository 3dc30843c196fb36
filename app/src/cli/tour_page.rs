//! The tour's report as a page people read (`index.html`: an inlined stylesheet, a table
//! of contents, each experiment a section with its verdict in a box, its table with the
//! numbers aligned and its pictures side by side, each with a caption) and as text
//! (`summary.md`, the same content). The page loads nothing from the network: it opens
//! offline, the pictures are the SVG files beside it.

use std::fmt::Write as _;

/// A picture of the report, with what the tests check in it.
pub struct Picture {
    /// File name, beside the page.
    pub file: String,
    /// The chart's title (the image's `alt` text).
    pub title: String,
    /// Axis labels and legend entries, as drawn.
    pub x_label: String,
    pub y_label: String,
    pub legend: Vec<String>,
    /// What the picture shows and what to look at.
    pub caption: String,
}

/// One experiment of the report.
pub struct Section {
    pub title: String,
    /// The finding, computed from the runs.
    pub verdict: String,
    /// Table, header row first.
    pub table: Vec<Vec<String>>,
    pub pictures: Vec<Picture>,
}

/// The stylesheet: system fonts only, figures in as many columns of at least 460 px as
/// fit (one on a phone), wide tables scrolling inside their box rather than the page.
const STYLE: &str = "
:root { --ink: #1f2328; --muted: #57606a; --line: #d0d7de; --accent: #0969da; --paper: #ffffff; }
* { box-sizing: border-box; }
body { margin: 0; background: #f6f8fa; color: var(--ink); overflow-wrap: anywhere;
  font: 16px/1.55 system-ui, -apple-system, 'Segoe UI', Roboto, 'Helvetica Neue', Arial, sans-serif; }
main { max-width: 1280px; margin: 0 auto; padding: 1.5rem clamp(0.6rem, 3vw, 2rem) 2rem; }
h1 { font-size: 2rem; margin: 0.5rem 0; }
h2 { font-size: 1.35rem; line-height: 1.3; margin: 0 0 0.75rem; }
a { color: var(--accent); }
.lead { color: var(--muted); max-width: 62rem; }
nav, section { background: var(--paper); border: 1px solid var(--line); border-radius: 8px;
  padding: 1rem clamp(0.75rem, 2.5vw, 1.5rem); margin: 1.25rem 0; }
nav h2 { font-size: 1.1rem; }
nav ol { margin: 0; padding-left: 1.5rem; columns: 2 22rem; }
nav a { text-decoration: none; }
.verdict { background: #ddf4ff; border-left: 4px solid var(--accent); border-radius: 0 6px 6px 0;
  padding: 0.7rem 1rem; margin: 0 0 1rem; }
.table { overflow-x: auto; margin: 0 0 1rem; }
table { border-collapse: collapse; font-size: 0.95rem; }
th, td { padding: 0.35rem 0.8rem; border-bottom: 1px solid var(--line); text-align: left;
  white-space: nowrap; overflow-wrap: normal; }
th { background: #f6f8fa; font-weight: 600; white-space: normal; vertical-align: bottom; }
.num { text-align: right; font-variant-numeric: tabular-nums; }
.figures { display: grid; gap: 1rem;
  grid-template-columns: repeat(auto-fill, minmax(min(100%, 460px), 1fr)); }
figure { margin: 0; border: 1px solid var(--line); border-radius: 6px; padding: 0.5rem; }
figure img { display: block; width: 100%; max-width: 100%; height: auto; }
figcaption { color: var(--muted); font-size: 0.92rem; padding: 0.5rem 0.25rem 0.1rem; }
footer { color: var(--muted); font-size: 0.9rem; }
@media (max-width: 600px) { th, td { padding: 0.3rem 0.45rem; } table { font-size: 0.85rem; } }
code { font-family: ui-monospace, SFMono-Regular, Menlo, Consolas, monospace; font-size: 0.9em; }
";

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

/// The anchor of a section: its title's words, lower case, joined by `-`.
fn anchor(title: &str) -> String {
    let words: Vec<String> = title
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .map(str::to_ascii_lowercase)
        .collect();
    words.join("-")
}

/// A cell that holds a number (with a unit after it, as `750.2 µs`), aligned right.
fn numeric(cell: &str) -> bool {
    let first = cell.split_whitespace().next().unwrap_or("");
    first.trim_start_matches('+').parse::<f64>().is_ok()
}

/// The columns of a table's body whose every cell is a number.
fn numeric_columns(body: &[Vec<String>], width: usize) -> Vec<bool> {
    (0..width)
        .map(|j| !body.is_empty() && body.iter().all(|row| row.get(j).is_some_and(|c| numeric(c))))
        .collect()
}

fn table_html(html: &mut String, head: &[String], body: &[Vec<String>]) {
    let num = numeric_columns(body, head.len());
    let class = |j: usize| {
        if num.get(j) == Some(&true) {
            " class=\"num\""
        } else {
            ""
        }
    };
    html.push_str("<div class=\"table\"><table>\n<thead><tr>");
    for (j, h) in head.iter().enumerate() {
        let _ = write!(html, "<th{}>{}</th>", class(j), escape(h));
    }
    html.push_str("</tr></thead>\n<tbody>\n");
    for row in body {
        html.push_str("<tr>");
        for (j, c) in row.iter().enumerate() {
            let _ = write!(html, "<td{}>{}</td>", class(j), escape(c));
        }
        html.push_str("</tr>\n");
    }
    html.push_str("</tbody></table></div>\n");
}

/// `index.html`.
pub fn html(sections: &[Section]) -> String {
    let mut html = format!(
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
         <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
         <title>stormer tour</title>\n<style>{STYLE}</style>\n</head>\n<body>\n<main>\n\
         <h1>stormer tour</h1>\n<p class=\"lead\">The experiments of docs/scenes.md, run by \
         <code>stormer tour</code>. Each section gives its verdict, computed from the runs, \
         then the numbers and the pictures behind it. The same report as text: \
         <a href=\"summary.md\">summary.md</a>.</p>\n\
         <nav aria-label=\"Contents\">\n<h2>Contents</h2>\n<ol>\n"
    );
    for s in sections {
        let _ = writeln!(
            html,
            "<li><a href=\"#{}\">{}</a></li>",
            anchor(&s.title),
            escape(&s.title)
        );
    }
    html.push_str("</ol>\n</nav>\n");
    for s in sections {
        let _ = writeln!(
            html,
            "<section id=\"{}\">\n<h2>{}</h2>\n<p class=\"verdict\"><strong>Verdict:</strong> {}</p>",
            anchor(&s.title),
            escape(&s.title),
            escape(&s.verdict)
        );
        if let Some((head, body)) = s.table.split_first() {
            table_html(&mut html, head, body);
        }
        html.push_str("<div class=\"figures\">\n");
        for p in &s.pictures {
            let _ = writeln!(
                html,
                "<figure><img src=\"{}\" alt=\"{}\" data-x=\"{}\" data-y=\"{}\" data-legend=\"{}\">\
                 <figcaption>{}</figcaption></figure>",
                escape(&p.file),
                escape(&p.title),
                escape(&p.x_label),
                escape(&p.y_label),
                escape(&p.legend.join(";")),
                escape(&p.caption),
            );
        }
        html.push_str("</div>\n</section>\n");
    }
    html.push_str(
        "<footer><p>Written by <code>stormer tour</code>. The page is self-contained: the \
         pictures are the SVG files beside it, nothing is loaded from the network.</p></footer>\n\
         </main>\n</body>\n</html>\n",
    );
    html
}

/// `summary.md`.
pub fn markdown(sections: &[Section]) -> String {
    let mut md = String::from(
        "# stormer tour\n\nThe experiments of docs/scenes.md, each with its verdict computed from the runs.\n\n",
    );
    let cell = |c: &String| c.replace('|', "\\|");
    for s in sections {
        let _ = writeln!(md, "## {}\n\n**Verdict:** {}\n", s.title, s.verdict);
        if let Some((head, body)) = s.table.split_first() {
            let num = numeric_columns(body, head.len());
            let _ = writeln!(md, "| {} |", head.iter().map(cell).collect::<Vec<_>>().join(" | "));
            let rule: String = num.iter().map(|n| if *n { "---:|" } else { "---|" }).collect();
            let _ = writeln!(md, "|{rule}");
            for row in body {
                let _ = writeln!(md, "| {} |", row.iter().map(cell).collect::<Vec<_>>().join(" | "));
            }
            md.push('\n');
        }
        for p in &s.pictures {
            let _ = writeln!(md, "![{}]({})\n\n*{}*\n", p.title, p.file, p.caption);
        }
    }
    md
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_told_from_words() {
        for n in ["2.025e-1", "+1.5e-3", "750.2 µs", "0.0125", "-3"] {
            assert!(numeric(n), "{n}");
        }
        for w in ["stays bounded", "rk4", "", "the ball lands at t = 1.3 s"] {
            assert!(!numeric(w), "{w}");
        }
        assert_eq!(anchor("E x B drift: the six schemes"), "e-x-b-drift-the-six-schemes");
    }

    #[test]
    fn the_page_escapes_and_aligns() {
        let section = Section {
            title: "A <b> & c".into(),
            verdict: "x < y".into(),
            table: vec![
                vec!["method".into(), "max |dE|".into()],
                vec!["rk4".into(), "1e-3".into()],
            ],
            pictures: vec![],
        };
        let page = html(std::slice::from_ref(&section));
        assert!(page.contains("<h2>A &lt;b&gt; &amp; c</h2>") && page.contains("x &lt; y"));
        assert!(page.contains("<th class=\"num\">max |dE|</th>") && page.contains("<td class=\"num\">1e-3</td>"));
        assert!(!page.contains("http"), "nothing from the network");
        let md = markdown(&[section]);
        assert!(md.contains("| method | max \\|dE\\| |\n|---|---:|\n"), "{md}");
    }
}
