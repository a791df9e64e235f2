package io.concord.core.content;

import org.junit.jupiter.api.Test;

import java.time.Instant;
import java.util.List;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** The SL codec on its own: test vectors (as JADE 4.3 writes them), operators, profiles, errors. */
class SlCodecTest {
    private final SlCodec sl = new SlCodec();

    /** Text that reads and writes back byte for byte, in the form JADE 4.3 writes (the operators' vectors are not checked against JADE). */
    static final List<String> VECTORS = List.of(
            "((action (agent-identifier :name a@P) (Sell :book (Book :title \"say \\\"hi\\\" \\ there\" :n 42))))",
            "((Owns (Book :d 0.0 :f 2.5 :n -3 :t false :title t2) (agent-identifier :name x@P)))",
            "((Book :bytes #8\"AQJByCI= :date 20231114T221320123Z :tags (sequence hello \"\" \"123\" \":x\" \"a b\" \"true\")))",
            "(true)",
            "(true (= 1 1) )",
            "((= (Book :title x) (set 1 2)))",
            "((iota ?x (Owns ?x ?x)))",
            "((and (p) (not true)))",
            "((or (p) (implies (q) (equiv (r) (s)))))",
            "((forall ?x (exists ?y (Owns ?x ?y))))",
            "((B (agent-identifier :name a@P) (U (agent-identifier :name b@P) (p))))",
            "((PG (agent-identifier :name a@P) (I (agent-identifier :name a@P) (done (action (agent-identifier :name a@P) (Sell))))))",
            "((all (sequence ?x ?y) (Owns ?x ?y)))");

    @Test
    void vectorsReadAndWriteBackByteForByte() throws Exception {
        for (String v : VECTORS) {
            assertEquals(v, sl.write(sl.read(v)), v);
        }
    }

    @Test
    void readsEachKindOfTerm() throws Exception {
        AbsCompound c = (AbsCompound) sl.read("((p :s \"a\\\"b\" :i -12 :h 0x1F :f 1.5e3 :b TRUE :d 20231114T221320123Z "
                + ":y #4\"AQI= :w word :v ?x :q (sequence 1 x)))").get(0);
        assertEquals(new AbsPrimitive("a\"b"), c.get("s"));
        assertEquals(new AbsPrimitive(-12L), c.get("i"));
        assertEquals(new AbsPrimitive(31L), c.get("h"));
        assertEquals(new AbsPrimitive(1500.0), c.get("f"));
        assertEquals(new AbsPrimitive(true), c.get("b"));
        assertEquals(new AbsPrimitive(Instant.parse("2023-11-14T22:13:20.123Z")), c.get("d"));
        assertArrayEquals(new byte[] {1, 2}, (byte[]) ((AbsPrimitive) c.get("y")).value());
        assertEquals(new AbsPrimitive("word"), c.get("w"));
        assertEquals(new AbsVariable("x"), c.get("v"));
        assertEquals(new AbsAggregate("sequence", List.of(new AbsPrimitive(1L), new AbsPrimitive("x"))), c.get("q"));
    }

    @Test
    void aBackslashIsKeptAsJadeKeepsIt() throws Exception {
        AbsCompound c = (AbsCompound) sl.read("((p \"a\\\\b\\n\"))").get(0);
        assertEquals(new AbsPrimitive("a\\\\b\\n"), c.slots().get(0).value());
    }

    @Test
    void aStringJadeCannotReadBackIsRefused() {
        assertThrows(ContentException.class, () -> sl.write(AbsCompound.positional("p", new AbsPrimitive("two words\\"))));
        assertThrows(ContentException.class, () -> sl.write(AbsCompound.positional("p", new AbsPrimitive("a\\\"b"))));
    }

    @Test
    void numberLikeStringsAreQuoted() throws Exception {
        assertEquals("((p \"+1\" \".5\" \"-x\" \"7a\" @x))", sl.write(AbsCompound.positional("p",
                new AbsPrimitive("+1"), new AbsPrimitive(".5"), new AbsPrimitive("-x"), new AbsPrimitive("7a"), new AbsPrimitive("@x"))));
    }

    @Test
    void profilesRefuseOperatorsTheyDoNotHave() throws Exception {
        SlCodec sl0 = new SlCodec(SlCodec.Profile.SL0, 64, 1000);
        SlCodec sl1 = new SlCodec(SlCodec.Profile.SL1, 64, 1000);
        assertTrue(assertThrows(SlParseException.class, () -> sl0.read("((not (p)))")).getMessage().contains("not in SL0"));
        assertEquals(1, sl1.read("((not (p)))").size());
        assertThrows(SlParseException.class, () -> sl1.read("((forall ?x (p ?x)))"));
        assertThrows(ContentException.class, () -> sl1.write(AbsCompound.positional("B", new AbsVariable("a"), AbsCompound.positional("p"))));
        assertEquals("fipa-sl0", sl0.languageName());
    }

    @Test
    void operatorsHaveTheirArity() {
        assertTrue(assertThrows(SlParseException.class, () -> sl.read("((and (p)))")).getMessage()
                .contains("and takes 2 argument(s), got 1"));
        assertThrows(SlParseException.class, () -> sl.read("((forall x (p)))"));
        assertThrows(SlParseException.class, () -> sl.read("((not :what (p)))"));
    }

    @Test
    void malformedTextNamesThePosition() {
        assertEquals(7, assertThrows(SlParseException.class, () -> sl.read("((p :s \"abc))")).position());
        assertEquals(1, assertThrows(SlParseException.class, () -> sl.read("((p :a 1 2))")).position());
        assertEquals(6, assertThrows(SlParseException.class, () -> sl.read("((p) x")).position());
        assertEquals(4, assertThrows(SlParseException.class, () -> sl.read("((p 12ab))")).position());
        assertTrue(assertThrows(SlParseException.class, () -> sl.read("((p #9\"AAAA))")).getMessage().contains("past the end"));
        assertTrue(assertThrows(SlParseException.class, () -> sl.read("()")).getMessage().contains("empty content"));
        assertTrue(assertThrows(SlParseException.class, () -> sl.read("((p :a))")).getMessage().contains(":a has no value"));
    }

    @Test
    void infiniteNumbersAreRefused() {
        assertThrows(SlParseException.class, () -> sl.read("((p 1e400))"));
        assertThrows(ContentException.class, () -> sl.write(AbsCompound.positional("p", new AbsPrimitive(Double.NaN))));
    }
}
