// Copyright 2026 the Spherekit Authors
// SPDX-License-Identifier: Apache-2.0 OR MIT

//! Where in the document a JSON parse error happened, as a path (`curves[0].points[2]`).

use crate::error::one_line;

/// A parse error's text, prefixed by the JSON path where it happened (`points[1][0]: number
/// out of range at line 1 column 31`) when the error is inside the document.
pub(crate) fn json_error(text: &str, e: &serde_json::Error) -> String {
    if e.line() == 0 {
        return e.to_string();
    }
    let line_start: usize = text
        .split_inclusive('\n')
        .take(e.line() - 1)
        .map(str::len)
        .sum();
    // serde_json's column counts the bytes of the line read so far; a syntax error is found
    // at the byte after the culprit (`[1 2]` stops at `2`), so that byte is not scanned.
    let mut offset = line_start + e.column();
    if e.classify() == serde_json::error::Category::Syntax {
        offset = offset.saturating_sub(1);
    }
    // An unknown key is named by the message: the path is the object holding it.
    let path = json_path_at(text, offset, e.to_string().starts_with("unknown field"));
    if path.is_empty() {
        e.to_string()
    } else {
        format!("{path}: {e}")
    }
}

/// The JSON path (`curves[0].points[2]`) of the value being read at byte `offset` of `text`,
/// found by scanning the brackets, keys and commas before it; empty at the top level. With
/// `parent`, the path of the object whose key is being read (without that key).
pub(crate) fn json_path_at(text: &str, offset: usize, parent: bool) -> String {
    enum Frame {
        Object {
            key: Option<String>,
            expecting_key: bool,
        },
        Array(usize),
    }
    let bytes = &text.as_bytes()[..offset.min(text.len())];
    let mut stack: Vec<Frame> = Vec::new();
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'"' => {
                let start = i + 1;
                i += 1;
                while i < bytes.len() && bytes[i] != b'"' {
                    i += if bytes[i] == b'\\' { 2 } else { 1 };
                }
                if let Some(Frame::Object { key, expecting_key }) = stack.last_mut()
                    && *expecting_key
                    && i < bytes.len()
                {
                    *key = Some(String::from_utf8_lossy(&bytes[start..i]).into_owned());
                    *expecting_key = false;
                }
            }
            b'{' => stack.push(Frame::Object {
                key: None,
                expecting_key: true,
            }),
            b'[' => stack.push(Frame::Array(0)),
            b'}' | b']' => {
                stack.pop();
            }
            b',' => match stack.last_mut() {
                Some(Frame::Array(index)) => *index += 1,
                Some(Frame::Object { key, expecting_key }) => {
                    *key = None;
                    *expecting_key = true;
                }
                None => {}
            },
            _ => {}
        }
        i += 1;
    }
    if parent && matches!(stack.last(), Some(Frame::Object { .. })) {
        stack.pop();
    }
    let mut path = String::new();
    for (depth, frame) in stack.iter().enumerate() {
        if depth == 12 {
            path.push('…');
            break;
        }
        match frame {
            Frame::Object { key: Some(key), .. } => {
                if !path.is_empty() {
                    path.push('.');
                }
                path.push_str(key);
            }
            Frame::Object { key: None, .. } => break,
            Frame::Array(index) => path.push_str(&format!("[{index}]")),
        }
    }
    one_line(&path)
}

#[cfg(test)]
mod tests {
    use super::json_path_at;

    fn at(text: &str, marker: &str, parent: bool) -> String {
        let offset = text.find(marker).expect("marker in text");
        json_path_at(text, offset, parent)
    }

    #[test]
    fn paths_of_nested_values() {
        let text = r#"{"curves":[{"points":[[1,0,0],[0,X,0]]}]}"#;
        assert_eq!(at(text, "X", false), "curves[0].points[1][1]");
        assert_eq!(at(r#"{"space":X}"#, "X", false), "space");
        assert_eq!(at("X", "X", false), "");
    }

    #[test]
    fn keys_with_brackets_commas_and_escapes() {
        let text = r#"{"a,b":{"c\"[d":[0,X]}}"#;
        assert_eq!(at(text, "X", false), "a,b.c\\\"[d[1]");
    }

    #[test]
    fn parent_object_of_an_unknown_key() {
        let text = r#"{"view":{"camra":1}}"#;
        assert_eq!(at(text, "camra", true), "view");
        assert_eq!(at(text, "1}", false), "view.camra");
    }

    #[test]
    fn deep_paths_are_cut() {
        let text = format!("{}X", "[".repeat(20));
        assert_eq!(at(&text, "X", false), format!("{}…", "[0]".repeat(12)));
    }

    #[test]
    fn control_characters_in_keys_stay_on_one_line() {
        let text = "{\"a\nb\":X}";
        assert_eq!(at(text, "X", false), "a\\nb");
    }
}
