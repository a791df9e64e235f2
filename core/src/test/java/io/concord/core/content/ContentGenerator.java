package io.concord.core.content;

import io.concord.core.acl.AID;
import io.concord.core.content.BookShop.Author;
import io.concord.core.content.BookShop.Book;
import io.concord.core.content.BookShop.Owns;
import io.concord.core.content.BookShop.Sell;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Random;
import java.util.Set;

/** Random content of the test ontology, from a seed. */
final class ContentGenerator {
    private static final String[] PIECES = {
        "a", "b", "Z", "x", "word", "0", "7", "-", "+", ".", " ", "  ", "\"", "\\", "(", ")", ":", "?", "#", "@",
        "é", "ß", "中文", "\uD83D\uDE00", "\t", "\n", "true", "false", "e", "E", "T", "_", "/", "'", "sequence", "|"
    };
    private final Random random;

    ContentGenerator(long seed) {
        random = new Random(seed);
    }

    Object contentElement() {
        switch (random.nextInt(6)) {
            case 4:
                return new Equals(book(1), random.nextBoolean() ? aid() : book(1));
            case 5:
                return random.nextBoolean() ? new TrueProposition() : new FalseProposition();
            case 0:
                return new Owns(aid(), book(0));
            case 1:
                return new Done(action());
            case 2:
                return new Result(action(), book(0));
            default:
                return action();
        }
    }

    Action action() {
        return new Action(aid(), sell());
    }

    Sell sell() {
        List<Book> more = random.nextInt(3) == 0 ? null : list(() -> book(1));
        return new Sell(book(0), more, random.nextBoolean() ? aid() : null, random.nextBoolean() ? string() : null);
    }

    Book book(int depth) {
        return new Book(string(), longValue(), random.nextBoolean() ? (Integer) random.nextInt() : null,
                doubleValue(), floatValue(), random.nextBoolean(),
                random.nextBoolean() ? Instant.ofEpochMilli(random.nextLong() % 4_102_444_800_000L + 4_102_444_800_000L / 2) : null,
                random.nextInt(3) == 0 ? bytes() : null,
                random.nextBoolean() ? list(this::string) : null,
                random.nextInt(3) == 0 ? longSet() : null,
                depth < 2 && random.nextBoolean() ? list(() -> author(depth + 1)) : null);
    }

    Author author(int depth) {
        return new Author(string(), random.nextBoolean() ? list(this::string) : null,
                depth < 3 && random.nextInt(3) == 0 ? author(depth + 1) : null);
    }

    AID aid() {
        AID aid = new AID(word() + "@" + word());
        if (random.nextBoolean()) {
            return new AID(aid.name(), "http://" + word() + ":7778/acc");
        }
        return aid;
    }

    String word() {
        StringBuilder b = new StringBuilder();
        int n = 1 + random.nextInt(8);
        for (int i = 0; i < n; i++) {
            b.append((char) ('a' + random.nextInt(26)));
        }
        return b.toString();
    }

    /**
     * Any string JADE can carry: all but a backslash at the end or before a quote (see SlCodec),
     * and all but {@code "true"} and {@code "false"} with their quotes, which JADE's reader turns
     * into {@code true} and {@code false} (docs/content.md).
     */
    String string() {
        if (random.nextInt(4) == 0) {
            return word();
        }
        StringBuilder b = new StringBuilder();
        int n = random.nextInt(7);
        for (int i = 0; i < n; i++) {
            b.append(PIECES[random.nextInt(PIECES.length)]);
        }
        String s = b.toString();
        if (s.equalsIgnoreCase("\"true\"") || s.equalsIgnoreCase("\"false\"")) {
            s = s + "x";
        }
        while (s.endsWith("\\") || s.contains("\\\"")) {
            s = s.replace("\\\"", "\\x\"");
            if (s.endsWith("\\")) {
                s = s + "y";
            }
        }
        return s;
    }

    long longValue() {
        switch (random.nextInt(3)) {
            case 0:
                return random.nextLong();
            case 1:
                return random.nextInt(2001) - 1000;
            default:
                return 0;
        }
    }

    double doubleValue() {
        switch (random.nextInt(4)) {
            case 0:
                return random.nextDouble();
            case 1:
                return (random.nextDouble() - 0.5) * Math.pow(10, random.nextInt(40) - 20);
            case 2:
                return random.nextInt(1000) - 500;
            default:
                double d = Double.longBitsToDouble(random.nextLong());
                return Double.isFinite(d) ? d : 0.0;
        }
    }

    float floatValue() {
        return random.nextBoolean() ? random.nextFloat() : (random.nextFloat() - 0.5f) * (float) Math.pow(10, random.nextInt(20) - 10);
    }

    byte[] bytes() {
        byte[] b = new byte[random.nextInt(12)];
        random.nextBytes(b);
        return b;
    }

    Set<Long> longSet() {
        Set<Long> s = new LinkedHashSet<>();
        int n = 1 + random.nextInt(4);
        for (int i = 0; i < n; i++) {
            s.add(longValue());
        }
        return s;
    }

    <T> List<T> list(java.util.function.Supplier<T> element) {
        List<T> l = new ArrayList<>();
        int n = random.nextInt(10) == 0 ? 0 : 1 + random.nextInt(3);
        for (int i = 0; i < n; i++) {
            l.add(element.get());
        }
        return l;
    }
}
