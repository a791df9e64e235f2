package io.concord.core.content;

import org.junit.jupiter.api.Test;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

/**
 * A fuzzer of the SL reader and the ontology mapping behind it: mutated valid content, token soup
 * and deep nesting must give a result or the codec's own exception, never another one (no
 * StackOverflowError, no runtime exception). Inputs: the system property {@code concord.sl.fuzz}
 * (100,000 by default); the seed: {@code concord.sl.seed}.
 */
class SlReaderFuzzTest {
    private static final int INPUTS = Integer.getInteger("concord.sl.fuzz", 100_000);
    private static final long SEED = Long.getLong("concord.sl.seed", 33L);
    private static final String ALPHABET = "()()::??##\"\"\\ \t\n-+.0123456789eETZxaz@é\uD83D\u0000";
    private static final String[] TOKENS = {
        "(", ")", "(sequence", "(set", "(action", "(and", "(iota", "(B", "(forall", ":name", ":title", "?x",
        "\"s\"", "#3\"abc", "#999999999\"", "#4\"ab", "123", "-1.5e3", "0x1F", "20231114T221320123Z", "true",
        "Book", "Sell", "(Book", "(Owns", "(agent-identifier", "(done", "(result", "(=", "\"", "\\", "??"
    };

    private final SlCodec codec = new SlCodec();
    private final BeanOntology ontology = BookShop.ontology();

    @Test
    void mutatedContentGivesOnlyTheCodecsOwnException() throws Exception {
        Random r = new Random(SEED);
        ContentGenerator g = new ContentGenerator(SEED);
        List<String> seeds = new ArrayList<>();
        for (int i = 0; i < 200; i++) {
            seeds.add(codec.write(ontology.toAbs(g.contentElement())));
        }
        int accepted = 0;
        int refused = 0;
        for (int i = 0; i < INPUTS; i++) {
            String input = switch (r.nextInt(3)) {
                case 0 -> mutate(seeds.get(r.nextInt(seeds.size())), r);
                case 1 -> soup(r);
                default -> nested(r);
            };
            if (readAndMap(input)) {
                accepted++;
            } else {
                refused++;
            }
        }
        // both outcomes must occur, or the fuzzer is not exploring
        assertTrue(accepted > 0 && refused > 0, "accepted " + accepted + ", refused " + refused);
    }

    @Test
    void nestingPastTheLimitIsRefusedWithoutRecursingIntoIt() {
        String deep = "(" + "(p ".repeat(100_000) + "a" + ")".repeat(100_001);
        SlParseException e = assertThrows(SlParseException.class, () -> codec.read(deep));
        assertTrue(e.getMessage().contains("nesting deeper than the limit of " + SlCodec.DEFAULT_MAX_DEPTH), e.getMessage());
        // the content's own parenthesis is level 1, so the refused compound is the max-th, at 1 + 3 * (max - 1)
        assertEquals(1 + 3 * (SlCodec.DEFAULT_MAX_DEPTH - 1), e.position());
    }

    @Test
    void nestingUpToTheLimitIsRead() throws Exception {
        int depth = SlCodec.DEFAULT_MAX_DEPTH;
        String text = "(" + "(p ".repeat(depth - 1) + "x" + ")".repeat(depth - 1) + ")";
        assertEquals(1, codec.read(text).size());
        String tooDeep = "(" + "(p ".repeat(depth) + "x" + ")".repeat(depth) + ")";
        assertThrows(SlParseException.class, () -> codec.read(tooDeep));
    }

    @Test
    void textOverTheLengthLimitIsRefusedBeforeReading() {
        SlCodec small = new SlCodec(SlCodec.Profile.SL, 8, 100);
        String text = "((p " + "x".repeat(200) + "))";
        SlParseException e = assertThrows(SlParseException.class, () -> small.read(text));
        assertTrue(e.getMessage().contains("over the limit of 100"), e.getMessage());
    }

    /** True if read and mapped, false if refused with the codec's exception; fails on anything else. */
    private boolean readAndMap(String input) {
        try {
            for (AbsObject abs : codec.read(input)) {
                try {
                    ontology.fromAbs(abs);
                } catch (ContentException e) {
                    // a well-formed text that breaks the schema: refused by the ontology, as it should be
                }
            }
            return true;
        } catch (SlParseException e) {
            assertTrue(e.position() >= 0 && e.position() <= input.length(), "position " + e.position() + " for " + input);
            return false;
        } catch (Throwable t) {
            fail("unexpected " + t + " for input: " + input, t);
            return false;
        }
    }

    private static String mutate(String s, Random r) {
        StringBuilder b = new StringBuilder(s);
        int edits = 1 + r.nextInt(4);
        for (int k = 0; k < edits && b.length() > 0; k++) {
            int at = r.nextInt(b.length());
            switch (r.nextInt(5)) {
                case 4 -> {
                    // a well-formed text of the wrong shape: a set where a sequence belongs, or the reverse
                    String t = b.toString();
                    b.setLength(0);
                    b.append(r.nextBoolean() ? t.replaceFirst("\\(sequence", "(set") : t.replaceFirst("\\(set", "(sequence"));
                }
                case 0 -> b.insert(at, ALPHABET.charAt(r.nextInt(ALPHABET.length())));
                case 1 -> b.deleteCharAt(at);
                case 2 -> b.setCharAt(at, ALPHABET.charAt(r.nextInt(ALPHABET.length())));
                default -> b.setLength(at);
            }
        }
        return b.toString();
    }

    private static String soup(Random r) {
        StringBuilder b = new StringBuilder("(");
        int n = r.nextInt(20);
        for (int i = 0; i < n; i++) {
            b.append(TOKENS[r.nextInt(TOKENS.length)]).append(r.nextBoolean() ? " " : "");
        }
        return b.append(r.nextBoolean() ? ")" : "").toString();
    }

    private static String nested(Random r) {
        int depth = r.nextInt(200);
        return "(" + "(p :s ".repeat(depth) + "x" + ")".repeat(r.nextInt(depth + 1)) + ")";
    }
}
