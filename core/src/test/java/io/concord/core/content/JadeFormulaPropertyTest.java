package io.concord.core.content;

import jade.content.abs.AbsContentElement;
import jade.content.lang.sl.SLCodec;
import jade.content.lang.sl.SLOntology;
import jade.content.onto.BeanOntology;
import jade.content.onto.Ontology;

import org.junit.jupiter.api.Test;

import java.util.List;
import java.util.Random;

import static org.junit.jupiter.api.Assertions.assertEquals;

/**
 * Random SL2 formulas (connectives, quantifiers, modal operators, referential expressions, over
 * {@code =}, {@code true}, {@code false}, the book ontology's {@code Owns}, and {@code done} and
 * {@code result} of an {@code (action agent (Sell :book (Book ...)))}) mean the same to
 * Concord and JADE 4.3 (over its SL ontology), both ways: written by Concord, JADE reads them as
 * the same formula and writes them back byte for byte; written by JADE (from the same formula as
 * JADE's abstract objects), Concord reads them as the same formula and writes them back byte for
 * byte. Both tests draw the same formulas. Cases: {@code concord.sl.cases}; seed: {@code concord.sl.seed}.
 */
class JadeFormulaPropertyTest {
    private static final int CASES = Integer.getInteger("concord.sl.cases", 5_000);
    private static final long SEED = Long.getLong("concord.sl.seed", 33L);
    private static final String[] UNARY_OR_BINARY = {"not", "and", "or", "implies", "equiv"};
    private static final String[] MODAL = {"B", "U", "PG", "I"};
    private static final String[] QUANTIFIER = {"forall", "exists"};
    private static final String[] IRE = {"iota", "any", "all"};

    private final Random random = new Random(SEED);
    private final ContentGenerator strings = new ContentGenerator(SEED);
    private final SLCodec jade = new SLCodec();
    private final Ontology jadeOntology;
    private final SlCodec concord = new SlCodec();

    JadeFormulaPropertyTest() throws Exception {
        BeanOntology ontology = new BeanOntology("book-shop", SLOntology.getInstance());
        ontology.add(JadeBookShop.JAuthor.class);
        ontology.add(JadeBookShop.JBook.class);
        ontology.add(JadeBookShop.JOwns.class);
        ontology.add(JadeBookShop.JSell.class);
        jadeOntology = ontology;
    }

    @Test
    void jadeReadsConcordsFormulasAsTheSameFormulas() throws Exception {
        for (int i = 0; i < CASES; i++) {
            AbsObject formula = formula(0);
            String text = concord.write(formula);
            String jadeText;
            try {
                jadeText = jade.encode(jadeOntology, jade.decode(jadeOntology, text));
            } catch (Exception e) {
                throw new AssertionError(where(i) + ": JADE cannot read " + text, e);
            }
            assertEquals(text, jadeText, where(i));
            assertEquals(List.of(formula), concord.read(jadeText), where(i));
        }
    }

    @Test
    void concordReadsJadesFormulasAsTheSameFormulas() throws Exception {
        for (int i = 0; i < CASES; i++) {
            AbsObject formula = formula(0);
            String jadeText;
            try {
                jadeText = jade.encode(jadeOntology, (AbsContentElement) JadeMapping.toJadeAbs(formula, jadeOntology, true));
            } catch (Exception e) {
                throw new AssertionError(where(i) + ": JADE cannot write " + formula, e);
            }
            List<AbsObject> read;
            try {
                read = concord.read(jadeText);
            } catch (SlParseException e) {
                throw new AssertionError(where(i) + ": Concord cannot read JADE's " + jadeText, e);
            }
            assertEquals(List.of(formula), read, where(i) + ": Concord reads JADE's " + jadeText);
            assertEquals(jadeText, concord.write(read), where(i) + ": Concord writes back what it read");
        }
    }

    private static String where(int i) {
        return "case " + i + " (seed " + SEED + ")";
    }

    private AbsObject formula(int depth) {
        int choice = depth >= 4 ? random.nextInt(3) : random.nextInt(10);
        switch (choice) {
            case 0:
                return new AbsPrimitive(random.nextBoolean());
            case 1:
                return AbsCompound.positional("=", term(depth + 1), term(depth + 1));
            case 2:
                return AbsCompound.positional("Owns", variable(), variable());
            case 3: {
                String op = UNARY_OR_BINARY[random.nextInt(UNARY_OR_BINARY.length)];
                return op.equals("not") ? AbsCompound.positional(op, formula(depth + 1))
                        : AbsCompound.positional(op, formula(depth + 1), formula(depth + 1));
            }
            case 4:
                return AbsCompound.positional(QUANTIFIER[random.nextInt(2)], variable(), formula(depth + 1));
            case 5:
                return AbsCompound.positional(MODAL[random.nextInt(MODAL.length)], agent(), formula(depth + 1));
            case 6:
                return AbsCompound.positional("done", action());
            case 7:
                return AbsCompound.positional("result", action(), term(depth + 1));
            default:
                return AbsCompound.positional("=", variable(), AbsCompound.positional(IRE[random.nextInt(3)], variable(), formula(depth + 1)));
        }
    }

    private AbsObject term(int depth) {
        switch (random.nextInt(depth >= 4 ? 4 : 6)) {
            case 0:
                return new AbsPrimitive(strings.longValue());
            case 1:
                return new AbsPrimitive(string());
            case 2:
                return variable();
            case 3:
                return new AbsPrimitive(strings.doubleValue());
            case 4:
                return new AbsAggregate(random.nextBoolean() ? "set" : "sequence", List.of(term(depth + 1), term(depth + 1)));
            default:
                return AbsCompound.positional("iota", variable(), formula(depth + 1));
        }
    }

    /** A string JADE writes as Concord does: not one JADE leaves bare and reads as something else (docs/content.md). */
    private String string() {
        String s = strings.string();
        return s.startsWith(".") || s.startsWith("+") || s.startsWith("??") ? "x" + s : s;
    }

    /** {@code (action agent (Sell :book (Book ...)))}, the book's slots in the order JADE's schema gives them. */
    private AbsObject action() {
        List<AbsCompound.Slot> book = new java.util.ArrayList<>();
        if (random.nextBoolean()) {
            book.add(new AbsCompound.Slot("pages", new AbsPrimitive(strings.longValue())));
        }
        if (random.nextBoolean()) {
            book.add(new AbsCompound.Slot("price", new AbsPrimitive(strings.doubleValue())));
        }
        book.add(new AbsCompound.Slot("title", new AbsPrimitive(string())));
        AbsObject sell = new AbsCompound("Sell", List.of(new AbsCompound.Slot("book", new AbsCompound("Book", book))));
        return AbsCompound.positional("action", agent(), sell);
    }

    private AbsVariable variable() {
        return new AbsVariable(strings.word());
    }

    private AbsObject agent() {
        return new AbsCompound("agent-identifier", List.of(new AbsCompound.Slot("name", new AbsPrimitive(strings.word() + "@P"))));
    }
}
