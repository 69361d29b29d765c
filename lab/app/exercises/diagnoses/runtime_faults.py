"""Runtime family: the file cannot be judged (exit status 2) — it does not compile, raises,
runs out of time or memory, prints too much, leaves, crashes or returns the wrong kind of value.

Details come from :mod:`lab.app.exercises.runner` and :mod:`lab.app.exercises.sandbox`;
the checker adds ``call`` (the call that failed, e.g. ``menger(2)``) and ``file``.
"""
from __future__ import annotations

from lab.app.exercises.diagnoses.codes import register


def _where_en(d: dict) -> str:
    parts = []
    if d.get("line"):
        parts.append(f"line {d['line']}")
    if d.get("call"):
        parts.append(f"while running {d['call']}")
    elif d.get("stage") == "import":
        parts.append("while the file was loaded")
    return f" ({', '.join(parts)})" if parts else ""


def _where_ja(d: dict) -> str:
    parts = []
    if d.get("line"):
        parts.append(f"{d['line']} 行目")
    if d.get("call"):
        parts.append(f"{d['call']} の実行中")
    elif d.get("stage") == "import":
        parts.append("ファイルの読み込み中")
    return f"（{'、'.join(parts)}）" if parts else ""


register("syntax-error", "runtime",
         "the file is not valid Python: {message} at line {line}: {text}",
         "ファイルが Python として正しくありません: {line} 行目の {text} — {message}", status=2)

register("exception", "runtime",
         lambda d: f"the code raised {d.get('type', 'an exception')}: {d.get('message', '')}{_where_en(d)}",
         lambda d: f"実行中に例外 {d.get('type', '')} が発生しました: {d.get('message', '')}{_where_ja(d)}",
         status=2)

register("not-implemented", "runtime",
         lambda d: f"the function still raises NotImplementedError{_where_en(d)}: replace the starter's "
                   "`raise NotImplementedError` with your code",
         lambda d: f"関数がまだ NotImplementedError を送出しています{_where_ja(d)}。ひな形の "
                   "`raise NotImplementedError` を自分のコードに書き換えてください",
         status=2)

register("missing-function", "runtime",
         lambda d: f"the file defines no function `{d.get('function')}`"
                   + (f" (it defines: {', '.join(d['defined'])})" if d.get("defined") else "")
                   + "; keep the starter's name and signature",
         lambda d: f"ファイルに関数 `{d.get('function')}` がありません"
                   + (f"（定義されているのは {', '.join(d['defined'])}）" if d.get("defined") else "")
                   + "。ひな形の関数名と引数のまま書いてください",
         status=2)

register("time-limit", "runtime",
         lambda d: f"stopped after {d.get('seconds', 0):g} s of {'CPU' if d.get('clock') == 'cpu' else 'wall-clock'} "
                   "time: an endless loop, or far too much work (the checker's cases take well under a second)",
         lambda d: f"{'CPU ' if d.get('clock') == 'cpu' else ''}時間 {d.get('seconds', 0):g} 秒で打ち切りました。"
                   "無限ループか、計算量が大きすぎます（採点のケースは 1 秒もかかりません）",
         status=2)

register("memory-limit", "runtime",
         lambda d: f"ran out of its {d.get('memory_mb', '?')} MiB of memory{_where_en(d)}: "
                   "something grows without bound or allocates a huge array",
         lambda d: f"メモリ上限 {d.get('memory_mb', '?')} MiB を超えました{_where_ja(d)}。"
                   "際限なく増えるリストか、巨大な配列の確保があります",
         status=2)

register("output-limit", "runtime",
         lambda d: f"printed more than {d.get('bytes', 0):,} bytes and was stopped: remove the prints in loops",
         lambda d: f"{d.get('bytes', 0):,} バイトを超える出力をしたため停止しました。ループ内の print を消してください",
         status=2)

register("exited", "runtime",
         lambda d: f"the program ended by itself (exit status {d.get('message')}){_where_en(d)} instead of "
                   "returning: do not call sys.exit(), exit() or os._exit() in a solution",
         lambda d: f"値を返さずにプログラムが終了しました（終了ステータス {d.get('message')}）{_where_ja(d)}。"
                   "解答の中で sys.exit()・exit()・os._exit() を呼ばないでください",
         status=2)

register("crashed", "runtime",
         "the Python process crashed (signal {signal}): usually memory corrupted through ctypes or a "
         "compiled extension",
         "Python のプロセスが異常終了しました（シグナル {signal}）。ctypes や拡張モジュールによるメモリ破壊が原因のことが多いです",
         status=2)

register("wrong-return-type", "runtime",
         lambda d: f"wrong kind of result{' from ' + d['call'] if d.get('call') else ''}: {d.get('message')}",
         lambda d: f"戻り値の型が違います{'（' + d['call'] + '）' if d.get('call') else ''}: {d.get('message_ja') or d.get('message')}",
         status=2)

register("checker-error", "runtime",
         "the checker itself failed on this submission ({message}); please tell your teacher",
         "このファイルの採点中に採点プログラム自体が失敗しました（{message}）。先生に知らせてください",
         status=2)
