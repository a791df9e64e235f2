package io.concord.core.content;

import jade.content.onto.annotations.AggregateSlot;

import java.util.Date;
import java.util.List;
import java.util.Set;

/** The same ontology as {@link BookShop}, as JADE beans for JADE's BeanOntology. */
public final class JadeBookShop {
    private JadeBookShop() {
    }

    /** An author. */
    @jade.content.onto.annotations.Element(name = "Author")
    public static class JAuthor implements jade.content.Concept {
        private String name;
        private List<String> aliases;
        private JAuthor mentor;

        @jade.content.onto.annotations.Slot(mandatory = true)
        public String getName() { return name; }
        public void setName(String v) { name = v; }
        public List<String> getAliases() { return aliases; }
        public void setAliases(List<String> v) { aliases = v; }
        public JAuthor getMentor() { return mentor; }
        public void setMentor(JAuthor v) { mentor = v; }
    }

    /** A book. */
    @jade.content.onto.annotations.Element(name = "Book")
    public static class JBook implements jade.content.Concept {
        private String title;
        private long pages;
        private Integer edition;
        private double price;
        private float rating;
        private boolean used;
        private Date published;
        private byte[] cover;
        private List<String> tags;
        private Set<Long> isbns;
        private List<JAuthor> authors;

        @jade.content.onto.annotations.Slot(mandatory = true)
        public String getTitle() { return title; }
        public void setTitle(String v) { title = v; }
        public long getPages() { return pages; }
        public void setPages(long v) { pages = v; }
        public Integer getEdition() { return edition; }
        public void setEdition(Integer v) { edition = v; }
        public double getPrice() { return price; }
        public void setPrice(double v) { price = v; }
        public float getRating() { return rating; }
        public void setRating(float v) { rating = v; }
        public boolean isUsed() { return used; }
        public void setUsed(boolean v) { used = v; }
        public Date getPublished() { return published; }
        public void setPublished(Date v) { published = v; }
        public byte[] getCover() { return cover; }
        public void setCover(byte[] v) { cover = v; }
        public List<String> getTags() { return tags; }
        public void setTags(List<String> v) { tags = v; }
        @AggregateSlot(type = Long.class)
        public Set<Long> getIsbns() { return isbns; }
        public void setIsbns(Set<Long> v) { isbns = v; }
        public List<JAuthor> getAuthors() { return authors; }
        public void setAuthors(List<JAuthor> v) { authors = v; }
    }

    /** Selling a book. */
    @jade.content.onto.annotations.Element(name = "Sell")
    public static class JSell implements jade.content.AgentAction {
        private JBook book;
        private List<JBook> more;
        private jade.core.AID buyer;
        private String remark;

        @jade.content.onto.annotations.Slot(mandatory = true)
        public JBook getBook() { return book; }
        public void setBook(JBook v) { book = v; }
        public List<JBook> getMore() { return more; }
        public void setMore(List<JBook> v) { more = v; }
        public jade.core.AID getBuyer() { return buyer; }
        public void setBuyer(jade.core.AID v) { buyer = v; }
        @jade.content.onto.annotations.Slot(name = "note")
        public String getRemark() { return remark; }
        public void setRemark(String v) { remark = v; }
    }

    /** Who owns a book. */
    @jade.content.onto.annotations.Element(name = "Owns")
    public static class JOwns implements jade.content.Predicate {
        private jade.core.AID owner;
        private JBook book;

        public jade.core.AID getOwner() { return owner; }
        public void setOwner(jade.core.AID v) { owner = v; }
        public JBook getBook() { return book; }
        public void setBook(JBook v) { book = v; }
    }

    static jade.content.onto.Ontology ontology() throws jade.content.onto.BeanOntologyException {
        jade.content.onto.BeanOntology o = new jade.content.onto.BeanOntology("book-shop");
        o.add(JAuthor.class);
        o.add(JBook.class);
        o.add(JSell.class);
        o.add(JOwns.class);
        return o;
    }
}
