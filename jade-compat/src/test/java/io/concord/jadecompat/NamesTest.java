package io.concord.jadecompat;

import io.concord.jadecompat.internal.Names;
import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

/** JADE's agent names as Concord words and back: the same name back for every name, the encoded one a word. */
class NamesTest {
    @Test
    void everyNameComesBackAsItWasAndIsAWordInBetween() {
        String[] names = {"timetable agent", "plain", "100%", "a%20b", "(x)", "say \"hi\"", "été", "tab\there", "a b@plat"};
        for (String n : names) {
            String word = Names.encodeFull(n);
            assertEquals(n, Names.decode(word), "round trip of " + n);
            String local = word.contains("@") ? word.substring(0, word.lastIndexOf('@')) : word;
            assertEquals(true, local.chars().allMatch(c -> c > ' ' && c < 0x7f && c != '(' && c != ')' && c != '"' && c != '@'),
                    n + " became " + word + ", not a Concord word");
        }
        assertEquals("plain", Names.encodeLocal("plain"));
        assertEquals("timetable%20agent", Names.encodeLocal("timetable agent"));
        assertEquals("a%2520b", Names.encodeLocal("a%20b"));
        assertEquals("timetable%20agent@shop", Names.encodeFull("timetable agent@shop"));
    }
}
