package io.concord.core.content;

import io.concord.core.acl.AclMessage;
import io.concord.core.acl.Performative;

import org.junit.jupiter.api.Test;

import java.util.List;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

/** A bean ontology of getter/setter classes, as JADE users write them, maps as records do. */
class BeanClassesTest {

    /** A JADE-style bean. */
    public static class Paper implements Concept {
        private String title;
        private int pages;
        private boolean signed;
        private List<String> tags;

        public Paper() {
        }

        @Slot(mandatory = true)
        public String getTitle() { return title; }
        public void setTitle(String v) { title = v; }
        public int getPages() { return pages; }
        public void setPages(int v) { pages = v; }
        public boolean isSigned() { return signed; }
        public void setSigned(boolean v) { signed = v; }
        @Slot(name = "keywords", cardMax = 3)
        public List<String> getTags() { return tags; }
        public void setTags(List<String> v) { tags = v; }
        /** Not a property: no setter. */
        public String getSummary() { return title + "/" + pages; }
    }

    /** The same, as a record. */
    @Element(name = "Paper")
    record PaperRecord(@Slot(mandatory = true) String title, int pages, boolean signed,
                       @Slot(name = "keywords", cardMax = 3) List<String> tags) implements Concept {
    }

    /** A predicate over the bean. */
    public static class Stocked implements Predicate {
        private Paper paper;
        private long count;

        public Stocked() {
        }

        public Paper getPaper() { return paper; }
        public void setPaper(Paper v) { paper = v; }
        public long getCount() { return count; }
        public void setCount(long v) { count = v; }
    }

    @Test
    void aBeanWritesAsTheSameRecordWould() throws Exception {
        Paper p = new Paper();
        p.setTitle("On Agents");
        p.setPages(12);
        p.setSigned(true);
        p.setTags(List.of("fipa", "sl"));
        BeanOntology beans = new BeanOntology("papers", Paper.class, Stocked.class);
        BeanOntology records = new BeanOntology("papers", PaperRecord.class);
        String fromBean = new SlCodec().write(beans.toAbs(p));
        assertEquals("((Paper :keywords (sequence fipa sl) :pages 12 :signed true :title \"On Agents\"))", fromBean);
        assertEquals(fromBean, new SlCodec().write(records.toAbs(new PaperRecord("On Agents", 12, true, List.of("fipa", "sl")))));
    }

    @Test
    void aBeanComesBackThroughTheContentManager() throws Exception {
        ContentManager cm = new ContentManager().register(new SlCodec()).register(new BeanOntology("papers", Paper.class, Stocked.class));
        Paper p = new Paper();
        p.setTitle("T");
        Stocked s = new Stocked();
        s.setPaper(p);
        s.setCount(4);
        AclMessage msg = new AclMessage(Performative.INFORM);
        cm.fill(msg, s);
        assertEquals("((Stocked 4 (Paper :pages 0 :signed false :title T)))", msg.getContent());
        Stocked back = (Stocked) cm.extract(msg);
        assertEquals(4, back.getCount());
        assertEquals("T", back.getPaper().getTitle());
        msg.setContent("((Stocked 4 (Paper :title T :keywords (sequence a b c d))))");
        assertTrue(assertThrows(ContentException.class, () -> cm.extract(msg)).reason().contains("allowed 0..3"));
    }

    record Give(@Slot(position = 0) String what, @Slot(position = 1) int count) implements AgentAction {
    }

    record HalfPlaced(@Slot(position = 0) String a, String b) implements AgentAction {
    }

    @Test
    void slotPositionsOrderAnActionAndWriteItByPosition() throws Exception {
        BeanOntology o = new BeanOntology("give", Give.class);
        SlCodec sl = new SlCodec();
        String text = sl.write(o.toAbs(new Action(new io.concord.core.acl.AID("a@P"), new Give("z", 2))));
        assertEquals("((action (agent-identifier :name a@P) (Give z 2)))", text);
        assertEquals(new Action(new io.concord.core.acl.AID("a@P"), new Give("z", 2)), o.fromAbs(sl.read(text).get(0)));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> new BeanOntology("x", HalfPlaced.class))
                .getMessage().contains("own @Slot(position)"));
    }
}
