package io.concord.core.codec;

import io.concord.core.acl.AID;
import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;

/** Generates random but valid ACL messages from a seed, with the characters that break codecs. */
final class AclGenerator {
    private static final String NASTY = " \t\n\"\\()#:-0123456789éß€😀\u0001";
    private final SplittableRandom random;

    AclGenerator(long seed) {
        this.random = new SplittableRandom(seed);
    }

    AclMessage message() {
        Performative[] ps = Performative.values();
        AclMessage m = new AclMessage(ps[random.nextInt(ps.length)]);
        if (random.nextBoolean()) {
            m.setSender(aid(0));
        }
        int nr = random.nextInt(4);
        for (int i = 0; i < nr; i++) {
            m.addReceiver(aid(0));
        }
        if (random.nextInt(4) == 0) {
            m.addReplyTo(aid(0));
        }
        switch (random.nextInt(3)) {
            case 0 -> m.setContent(text(200));
            case 1 -> {
                byte[] b = new byte[random.nextInt(64)];
                random.nextBytes(b);
                m.setByteSequenceContent(b);
            }
            default -> { }
        }
        if (random.nextBoolean()) {
            m.setLanguage(maybeWord());
        }
        if (random.nextBoolean()) {
            m.setEncoding(maybeWord());
        }
        if (random.nextBoolean()) {
            m.setOntology(maybeWord());
        }
        if (random.nextBoolean()) {
            m.setProtocol(word());
        }
        if (random.nextBoolean()) {
            m.setConversationId(maybeWord());
        }
        if (random.nextBoolean()) {
            m.setReplyWith(maybeWord());
        }
        if (random.nextBoolean()) {
            m.setInReplyTo(maybeWord());
        }
        if (random.nextBoolean()) {
            m.setReplyByEpochMs(random.nextLong(0, 4_102_444_800_000L));
        }
        int nu = random.nextInt(3);
        for (int i = 0; i < nu; i++) {
            m.addUserDefinedParameter(paramName(), text(20));
        }
        return m;
    }

    AID aid(int depth) {
        String name = random.nextBoolean() ? word() + "@" + word() : nonEmpty(text(15));
        List<String> addresses = new ArrayList<>();
        int na = random.nextInt(3);
        for (int i = 0; i < na; i++) {
            addresses.add(random.nextBoolean() ? "udp://127.0.0." + random.nextInt(255) + ":" + random.nextInt(65536)
                    : nonEmpty(text(10)));
        }
        List<AID> resolvers = new ArrayList<>();
        if (depth < 2 && random.nextInt(5) == 0) {
            resolvers.add(aid(depth + 1));
        }
        Map<String, String> user = new LinkedHashMap<>();
        if (random.nextInt(5) == 0) {
            user.put(paramName(), text(8));
        }
        return new AID(name, addresses, resolvers, user);
    }

    private String nonEmpty(String s) {
        return s.isEmpty() ? "x" : s;
    }

    String word() {
        int n = 1 + random.nextInt(12);
        StringBuilder sb = new StringBuilder();
        sb.append((char) ('a' + random.nextInt(26)));
        for (int i = 1; i < n; i++) {
            int k = random.nextInt(38);
            sb.append(k < 26 ? (char) ('a' + k) : k < 36 ? (char) ('0' + k - 26) : k == 36 ? '-' : '.');
        }
        return sb.toString();
    }

    private String paramName() {
        String w = word();
        return w.startsWith("x-") ? "p" + w : w;
    }

    private String maybeWord() {
        return random.nextInt(3) == 0 ? text(20) : word();
    }

    String text(int max) {
        int n = random.nextInt(max + 1);
        StringBuilder sb = new StringBuilder();
        for (int i = 0; i < n; i++) {
            if (random.nextInt(3) == 0) {
                sb.appendCodePoint(NASTY.codePointAt(NASTY.offsetByCodePoints(0, random.nextInt(NASTY.codePointCount(0, NASTY.length())))));
            } else {
                sb.append((char) (0x21 + random.nextInt(0x5e)));
            }
        }
        return sb.toString();
    }
}
