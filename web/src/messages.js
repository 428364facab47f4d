// The inspector's messages: newest first, at most 30. Errors are kept until the document they
// were about is replaced (New, Open, a drop), then cleared, so no stale error survives.
const MAX = 30;

export function createMessages(box, onError) {
  return {
    add(text, error = false) {
      const d = document.createElement('div');
      d.className = 'msg' + (error ? ' error' : '');
      d.textContent = text;
      box.prepend(d);
      while (box.children.length > MAX) box.lastChild.remove();
      if (error && onError) onError(text);
    },
    // Remove the errors (they were about a document that is gone).
    clearErrors() {
      for (const el of [...box.querySelectorAll('.msg.error')]) el.remove();
      if (onError) onError('');
    },
  };
}
