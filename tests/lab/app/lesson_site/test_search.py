"""lab/app/lesson_site/search.py: the course's compound terms stay whole words in the Japanese index."""
from janome.tokenizer import Tokenizer

from lab.app.lesson_site.search import course_terms, search_options, user_dictionary


def test_without_the_terms_janome_cuts_them_up():
    words = [t.surface for t in Tokenizer().tokenize("隠面消去とスキャンライン")]
    assert "隠面消去" not in words and "スキャンライン" not in words


def test_with_the_terms_they_are_single_words(tmp_path):
    dic = user_dictionary(tmp_path / "terms.csv")
    words = [t.surface for t in Tokenizer(udic=str(dic), udic_enc="utf8").tokenize("隠面消去とスキャンラインで塗る")]
    assert words[:4] == ["隠面消去", "と", "スキャンライン", "で"]


def test_the_terms_file_holds_the_course_terms_and_the_options_name_janome(tmp_path):
    terms = course_terms()
    assert {"スキャンライン", "隠面消去", "Zバッファ", "同次座標", "グローシェーディング"} <= set(terms)
    assert len(terms) == len(set(terms))
    options = search_options(tmp_path / "t.csv")
    assert options["type"] == "sphinx.search.ja.JanomeSplitter" and options["user_dic"].endswith("t.csv")
