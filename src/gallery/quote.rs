//! Text the gallery's index quotes: a file name as one word of a shell
//! command (a command a reader copies must run what it shows, and nothing
//! else), and as a relative URL.

/// `word` as one word of a POSIX shell command: as it is when it holds
/// only letters, digits and `_ - . / , : = @ +`, else in single quotes
/// (each `'` inside written `'\''`). The empty word is `''`. A word with
/// a character `Error::printable` escapes (a control character,
/// a bidirectional override) is written in dollar-single quotes, that
/// character's UTF-8 bytes as `\xHH`, so that the page shows no escape
/// sequence and the command still names the file (POSIX.1-2024, bash,
/// zsh and ksh read `$'…'`).
pub(super) fn shell_word(word: &str) -> String {
    let plain = |c: char| c.is_ascii_alphanumeric() || "_-./,:=@+".contains(c);
    if !word.is_empty() && word.chars().all(plain) {
        word.to_string()
    } else if crate::error::Error::printable(word) != word {
        let mut out = String::from("$'");
        for c in word.chars() {
            let mut buf = [0; 4];
            let one = c.encode_utf8(&mut buf);
            if c == '\\' || c == '\'' {
                out.push('\\');
                out.push(c);
            } else if crate::error::Error::printable(one) != *one {
                for b in one.bytes() {
                    out.push_str(&format!("\\x{b:02X}"));
                }
            } else {
                out.push(c);
            }
        }
        out.push('\'');
        out
    } else {
        format!("'{}'", word.replace('\'', r"'\''"))
    }
}

/// `name` (a file name in the gallery's directory) as a relative URL:
/// every byte of its UTF-8 but the unreserved characters of RFC 3986
/// (letters, digits, `- . _ ~`) percent-encoded, so that `#`, `?`, `%`, a
/// space or a `:` before any `/` are part of the name, not of the URL's
/// syntax.
pub(super) fn url_path(name: &str) -> String {
    let mut out = String::with_capacity(name.len());
    for b in name.bytes() {
        if b.is_ascii_alphanumeric() || b"-._~".contains(&b) {
            out.push(char::from(b));
        } else {
            out.push_str(&format!("%{b:02X}"));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_name_that_the_shell_would_read_as_syntax_is_quoted() {
        assert_eq!(
            shell_word("examples/offset-kisch.toml"),
            "examples/offset-kisch.toml"
        );
        assert_eq!(shell_word("x;touch PWNED;#.toml"), "'x;touch PWNED;#.toml'");
        assert_eq!(shell_word("it's $(rm).toml"), r"'it'\''s $(rm).toml'");
        assert_eq!(shell_word(""), "''");
        assert_eq!(shell_word("a`b`"), "'a`b`'");
        assert_eq!(shell_word("é.toml"), "'é.toml'");
        // An escape sequence and a right-to-left override: as bytes in
        // `$'…'`, which bash reads back as the same name.
        assert_eq!(shell_word("k\u{1b}[1m's\\.toml"), r"$'k\x1B[1m\'s\\.toml'");
        assert_eq!(shell_word("a\u{202e}b"), r"$'a\xE2\x80\xAEb'");
    }

    #[test]
    fn url_syntax_in_a_name_is_percent_encoded() {
        assert_eq!(url_path("fig-63-velocity.svg"), "fig-63-velocity.svg");
        assert_eq!(url_path("a#b?c%d.svg"), "a%23b%3Fc%25d.svg");
        assert_eq!(url_path("x y:z.png"), "x%20y%3Az.png");
        assert_eq!(url_path("é.svg"), "%C3%A9.svg");
    }
}
