//! A class's answers summed up for the teacher ([`ClassSummary`]): per problem, how many
//! students answered it, how many got it right, the mean score (the mean of each answer's
//! share of entries right, an exact fraction), which mistakes of the catalogue were made how
//! often, and how many wrong answers no known mistake explains. Built from the verdicts of
//! `cagd check` ([`crate::diagnose_with`]); written as text, Markdown, LaTeX and JSON, in
//! English and Spanish, its words typed ([`ClassWord`]).

use cagd_keys::{escape_latex, escape_markdown, escape_text, latex_preamble, mathematics_in_words};
use cagd_problem::diagnosis::Catalogued;
use cagd_problem::{Mistake, Verdict};
use cagd_scalar::{BigInt, BigRational};
use cagd_words::{said, Lang, Message, Phrase};
use num_traits::Zero;
use serde_json::{json, Value};

/// One problem of the class: its answers counted.
#[derive(Debug, Clone, PartialEq)]
pub struct ProblemSummary {
    /// The problem's number, from 1, in the order the problems were first met.
    pub number: usize,
    /// Its title (as the first answer to it gives it).
    pub title: Option<String>,
    /// Its Spanish title (`es.title`), for the summary in Spanish.
    pub title_es: Option<String>,
    /// Its short name.
    pub name: Option<String>,
    /// How many students wrote an answer to it (`expected`).
    pub answered: usize,
    /// How many of those answers are right.
    pub right: usize,
    /// The sum of the answers' scores (each `right/entries`), exact.
    score_sum: BigRational,
    /// Each mistake of the catalogue diagnosed in a wrong answer, with how many answers it
    /// explains (an ambiguous diagnosis counts each of its mistakes), in the order met.
    pub mistakes: Vec<(Mistake, usize)>,
    /// How many wrong answers no known mistake explains.
    pub unexplained: usize,
}

impl ProblemSummary {
    fn new(number: usize, verdict: &Verdict) -> ProblemSummary {
        let meta = verdict.problem.as_ref().map(|p| &p.meta);
        ProblemSummary {
            number,
            title: meta.and_then(|m| m.title.clone()),
            title_es: meta
                .and_then(|m| m.es.as_ref())
                .and_then(|e| e.title.clone()),
            name: meta.and_then(|m| m.name.clone()),
            answered: 0,
            right: 0,
            score_sum: BigRational::zero(),
            mistakes: Vec::new(),
            unexplained: 0,
        }
    }

    /// The mean score of the answers, `Σ right_k/entries_k ÷ answered`, exact (0 when no one
    /// answered).
    pub fn mean_score(&self) -> BigRational {
        if self.answered == 0 {
            return BigRational::zero();
        }
        &self.score_sum / BigRational::from_integer(BigInt::from(self.answered))
    }

    /// How many answers are wrong.
    pub fn wrong(&self) -> usize {
        self.answered - self.right
    }

    /// What the problem is called in `lang`: its title (the Spanish one in Spanish), else its
    /// name; `None` when it has neither (then its number names it).
    pub fn label(&self, lang: Lang) -> Option<&str> {
        let es = match lang {
            Lang::Es => self.title_es.as_deref(),
            Lang::En => None,
        };
        es.or(self.title.as_deref()).or(self.name.as_deref())
    }

    /// The mistakes, the most frequent first (ties in the order met).
    pub fn by_frequency(&self) -> Vec<(Mistake, usize)> {
        let mut out = self.mistakes.clone();
        out.sort_by_key(|m| std::cmp::Reverse(m.1));
        out
    }

    /// Its JSON: `problem` (the number), `title` and `name` when given, `answered`, `right`,
    /// `mean_score` (an exact fraction, `"7/9"`), `mistakes` (`id`, `mistake`: the sentence in
    /// English, `count`), `unexplained`.
    pub fn to_json(&self) -> Value {
        let mistakes: Vec<Value> = self
            .by_frequency()
            .iter()
            .map(|(m, n)| json!({"id": m.id(), "mistake": m.english(), "count": n}))
            .collect();
        let mut out = json!({ "problem": self.number });
        if let Some(o) = out.as_object_mut() {
            if let Some(t) = &self.title {
                o.insert("title".into(), Value::String(t.clone()));
            }
            if let Some(n) = &self.name {
                o.insert("name".into(), Value::String(n.clone()));
            }
            o.insert("answered".into(), json!(self.answered));
            o.insert("right".into(), json!(self.right));
            o.insert(
                "mean_score".into(),
                Value::String(self.mean_score().to_string()),
            );
            o.insert("mistakes".into(), Value::Array(mistakes));
            o.insert("unexplained".into(), json!(self.unexplained));
        }
        out
    }

    /// The lines of its counts in `lang`: answers, right and mean score; then each mistake;
    /// then the answers no known mistake explains.
    fn lines(&self, lang: Lang) -> (Phrase, Vec<Phrase>) {
        let counts = ClassWord::Answers(self.answered)
            .phrase(lang)
            .then(Phrase::data(", "))
            .then(ClassWord::Right(self.right).phrase(lang))
            .then(Phrase::data(", "))
            .then(ClassWord::MeanScore(self.mean_score().to_string()).phrase(lang));
        let mut items: Vec<Phrase> = self
            .by_frequency()
            .into_iter()
            .map(|(mistake, count)| ClassWord::Made { mistake, count }.phrase(lang))
            .collect();
        if self.unexplained > 0 {
            items.push(ClassWord::Unexplained(self.unexplained).phrase(lang));
        }
        (counts, items)
    }

    /// Its heading in `lang`: `Problem 2: Coons patch`.
    fn heading(&self, lang: Lang) -> Phrase {
        let number = ClassWord::Problem(self.number).phrase(lang);
        match self.label(lang) {
            Some(l) => number.then(Phrase::data(format!(": {l}"))),
            None => number,
        }
    }
}

/// The summary of a class's answers for the teacher.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ClassSummary {
    /// The students, in the order met (an answer without a student's name counts as one
    /// student of no name).
    pub students: Vec<Option<String>>,
    /// Each problem, in the order first met.
    pub problems: Vec<ProblemSummary>,
    /// The caller's identifier of each problem (the key it was checked against), beside
    /// [`ClassSummary::problems`].
    ids: Vec<usize>,
}

impl ClassSummary {
    /// An empty summary.
    pub fn new() -> ClassSummary {
        ClassSummary::default()
    }

    /// Counts the verdict of `student`'s answer to the problem the caller calls `problem`
    /// (the same number for every student's answer to the same problem: `cagd check` numbers
    /// its keys). An answer is a verdict with an assessment (the student wrote `expected`);
    /// it is right when the verdict passed. A wrong answer counts each mistake its
    /// assessment diagnoses once, or, when none, as unexplained.
    pub fn add(&mut self, problem: usize, student: Option<&str>, verdict: &Verdict) {
        let student = student.map(str::to_string);
        if !self.students.contains(&student) {
            self.students.push(student);
        }
        let at = match self.ids.iter().position(|&id| id == problem) {
            Some(at) => at,
            None => {
                self.ids.push(problem);
                let number = self.problems.len() + 1;
                self.problems.push(ProblemSummary::new(number, verdict));
                self.problems.len() - 1
            }
        };
        let Some(p) = self.problems.get_mut(at) else {
            return;
        };
        let Some(a) = verdict.assessment.as_deref() else {
            return;
        };
        p.answered += 1;
        let total = a.total();
        if total > 0 {
            p.score_sum += BigRational::new(BigInt::from(a.right()), BigInt::from(total));
        }
        if verdict.passed() {
            p.right += 1;
            return;
        }
        let mistakes = a.mistakes();
        if mistakes.is_empty() {
            p.unexplained += 1;
        }
        for m in mistakes {
            match p.mistakes.iter_mut().find(|(k, _)| *k == m) {
                Some((_, n)) => *n += 1,
                None => p.mistakes.push((m, 1)),
            }
        }
    }

    /// Its JSON: `students` (how many) and `problems` ([`ProblemSummary::to_json`] each).
    pub fn to_json(&self) -> Value {
        json!({
            "students": self.students.len(),
            "problems": self.problems.iter().map(ProblemSummary::to_json).collect::<Vec<_>>(),
        })
    }

    /// The title line: `Class summary: 3 students`.
    fn title(&self, lang: Lang) -> Phrase {
        ClassWord::Summary
            .phrase(lang)
            .then(Phrase::data(": "))
            .then(ClassWord::Students(self.students.len()).phrase(lang))
    }

    /// As plain text in `lang`: the title, then each problem's heading, its counts and its
    /// mistakes, indented. A problem's title is data, shown as written on one line.
    pub fn text(&self, lang: Lang) -> String {
        let mut out = escape_text(&self.title(lang).text()) + "\n";
        for p in &self.problems {
            let (counts, items) = p.lines(lang);
            out += &format!(
                "\n{}\n  {}\n",
                escape_text(&p.heading(lang).text()),
                escape_text(&counts.text())
            );
            for item in items {
                out += &format!("  - {}\n", escape_text(&item.text()));
            }
        }
        out
    }

    /// As a Markdown document in `lang` (every word shown as written, never read as Markdown).
    pub fn markdown(&self, lang: Lang) -> String {
        let mut out = format!("# {}\n", escape_markdown(&self.title(lang).text()));
        for p in &self.problems {
            let (counts, items) = p.lines(lang);
            out += &format!(
                "\n## {}\n\n{}\n",
                escape_markdown(&p.heading(lang).text()),
                escape_markdown(&counts.text())
            );
            if !items.is_empty() {
                out.push('\n');
            }
            for item in items {
                out += &format!("- {}\n", escape_markdown(&item.text()));
            }
        }
        out
    }

    /// As LaTeX sections in `lang` (every word escaped), for a document of
    /// `cagd_keys::latex_key_document`.
    pub fn latex_body(&self, lang: Lang) -> String {
        let mut out = format!("\\section*{{{}}}\n", escape_latex(&self.title(lang).text()));
        for p in &self.problems {
            let (counts, items) = p.lines(lang);
            out += &format!(
                "\\subsection*{{{}}}\n{}\n",
                mathematics_in_words(&p.heading(lang)),
                escape_latex(&counts.text())
            );
            if !items.is_empty() {
                out += "\\begin{itemize}\n";
                for item in items {
                    out += &format!("\\item {}\n", mathematics_in_words(&item));
                }
                out += "\\end{itemize}\n";
            }
        }
        out
    }

    /// As a complete LaTeX document in `lang`; compiles with pdflatex.
    pub fn latex(&self, lang: Lang) -> String {
        latex_preamble(lang) + "\\begin{document}\n" + &self.latex_body(lang) + "\\end{document}\n"
    }
}

/// The words of a class summary, English and Spanish (the counts' plurals chosen by the
/// count).
#[derive(Debug, Clone, PartialEq)]
pub enum ClassWord {
    /// The title: "Class summary".
    Summary,
    /// How many students.
    Students(usize),
    /// A problem by its number.
    Problem(usize),
    /// How many answers.
    Answers(usize),
    /// How many answers are right.
    Right(usize),
    /// The mean score, an exact fraction.
    MeanScore(String),
    /// A mistake and how many answers it explains.
    Made {
        /// The mistake.
        mistake: Mistake,
        /// How many answers.
        count: usize,
    },
    /// How many wrong answers no known mistake explains.
    Unexplained(usize),
}

impl Message for ClassWord {
    fn phrase(&self, lang: Lang) -> Phrase {
        match self {
            ClassWord::Summary => said(lang, "Class summary", "Resumen de la clase", []),
            ClassWord::Students(1) => said(lang, "1 student", "1 alumno", []),
            ClassWord::Students(n) => said(lang, "‹› students", "‹› alumnos", [n.into()]),
            ClassWord::Problem(n) => said(lang, "Problem ‹›", "Problema ‹›", [n.into()]),
            ClassWord::Answers(1) => said(lang, "1 answer", "1 respuesta", []),
            ClassWord::Answers(n) => said(lang, "‹› answers", "‹› respuestas", [n.into()]),
            ClassWord::Right(1) => said(lang, "1 right", "1 correcta", []),
            ClassWord::Right(n) => said(lang, "‹› right", "‹› correctas", [n.into()]),
            ClassWord::MeanScore(s) => said(
                lang,
                "mean score ‹›",
                "puntuación media ‹›",
                [s.as_str().into()],
            ),
            ClassWord::Made { mistake, count: 1 } => said(
                lang,
                "‹›, once: «»",
                "‹›, una vez: «»",
                [mistake.id().into(), mistake.phrase(lang).into()],
            ),
            ClassWord::Made { mistake, count } => said(
                lang,
                "‹›, ‹› times: «»",
                "‹›, ‹› veces: «»",
                [
                    mistake.id().into(),
                    count.into(),
                    mistake.phrase(lang).into(),
                ],
            ),
            ClassWord::Unexplained(1) => said(
                lang,
                "1 wrong answer that no known mistake explains",
                "1 respuesta incorrecta que ningún error conocido explica",
                [],
            ),
            ClassWord::Unexplained(n) => said(
                lang,
                "‹› wrong answers that no known mistake explains",
                "‹› respuestas incorrectas que ningún error conocido explica",
                [n.into()],
            ),
        }
    }
}

#[cfg(test)]
#[allow(clippy::unwrap_used, clippy::indexing_slicing)]
mod tests {
    use super::*;

    #[test]
    fn every_word_is_worded_in_both_languages() {
        let mut words = vec![ClassWord::Summary, ClassWord::MeanScore("7/9".into())];
        for n in [0, 1, 2, 12] {
            words.extend([
                ClassWord::Students(n),
                ClassWord::Problem(n.max(1)),
                ClassWord::Answers(n),
                ClassWord::Right(n),
                ClassWord::Unexplained(n.max(1)),
            ]);
            for mistake in Mistake::all() {
                words.push(ClassWord::Made {
                    mistake,
                    count: n.max(1),
                });
            }
        }
        for w in &words {
            assert_eq!(cagd_words::check_both(w), Ok(()), "{w:?}");
        }
    }

    /// Two students answer the same Coons problem: one right, one with c_cd added.
    #[test]
    fn a_class_is_counted_per_problem() {
        use cagd_problem::diagnosis::CoonsMistake;
        use cagd_problem::{Limits, Problem, Settings};
        let problem = json!({
            "op": "coons", "title": "Coons",
            "c1": {"bezier": [[0, 0, 0], [1, 0, 1], [2, 0, 0]]},
            "c2": {"bezier": [[0, 2, 0], [1, 2, 1], [2, 2, 0]]},
            "d1": {"bezier": [[0, 0, 0], [0, 2, 0]]},
            "d2": {"bezier": [[2, 0, 0], [2, 2, 0]]}
        });
        let settings = Settings::default();
        let p = Problem::read(&problem, &Limits::DEFAULT).unwrap();
        let key = crate::Key::new(&p, &settings);
        let right = key.answer.as_ref().unwrap().result[0].1.to_json();
        let added = Mistake::Coons(CoonsMistake::CdAdded);
        let (_, wrong) = key.mistaken.iter().find(|(m, _)| *m == added).unwrap();
        let wrong = wrong.result[0].1.to_json();
        let mut summary = ClassSummary::new();
        for (student, surface) in [("ana", &right), ("bea", &wrong)] {
            let mut answer = problem.clone();
            answer["expected"] = json!({ "surface": surface });
            let read = std::sync::Arc::new(Problem::read(&answer, &Limits::DEFAULT).unwrap());
            let v = crate::diagnose_with(&key, &read, &settings);
            summary.add(0, Some(student), &v);
        }
        let p = &summary.problems[0];
        assert_eq!((p.answered, p.right, p.unexplained), (2, 1, 0));
        assert_eq!(p.mistakes, vec![(added, 1)]);
        let wrong_score = summary.to_json()["problems"][0]["mean_score"].clone();
        assert!(wrong_score.as_str().unwrap().contains('/'), "{wrong_score}");
        let text = summary.text(Lang::Es);
        assert!(text.starts_with("Resumen de la clase: 2 alumnos\n\nProblema 1: Coons\n  2 respuestas, 1 correcta, puntuación media "), "{text}");
        assert!(text.ends_with("  - coons.cd_added, una vez: sumó la superficie bilineal c_cd en lugar de restarla\n"), "{text}");
        let markdown = summary.markdown(Lang::En);
        assert!(markdown.contains("- coons.cd\\_added, once: added the bilinear patch c\\_cd instead of subtracting it\n"), "{markdown}");
    }

    #[test]
    fn an_empty_class_says_so() {
        let s = ClassSummary::new();
        assert_eq!(s.text(Lang::Es), "Resumen de la clase: 0 alumnos\n");
        assert_eq!(s.to_json(), json!({"students": 0, "problems": []}));
    }
}
