import jade.content.Concept;
import jade.content.onto.annotations.AggregateSlot;
import jade.content.onto.annotations.Slot;

import java.util.Date;
import java.util.List;

/** A book, as a JavaBean for JADE's BeanOntology: a mandatory title, authors, a price, pages, a date. */
public class Book implements Concept {
    private String title;
    private List<String> authors;
    private float price;
    private int pages;
    private Date published;

    @Slot(mandatory = true)
    public String getTitle() {
        return title;
    }

    public void setTitle(String title) {
        this.title = title;
    }

    @AggregateSlot(cardMin = 1)
    public List<String> getAuthors() {
        return authors;
    }

    public void setAuthors(List<String> authors) {
        this.authors = authors;
    }

    public float getPrice() {
        return price;
    }

    public void setPrice(float price) {
        this.price = price;
    }

    public int getPages() {
        return pages;
    }

    public void setPages(int pages) {
        this.pages = pages;
    }

    public Date getPublished() {
        return published;
    }

    public void setPublished(Date published) {
        this.published = published;
    }

    /** Its fields, in a fixed order. */
    public String describe() {
        return "title=" + title + " authors=" + authors + " price=" + price + " pages=" + pages
                + " published=" + (published == null ? "none" : Long.toString(published.getTime()));
    }

    /** A book. */
    public static Book of(String title, float price, int pages, Date published, String... authors) {
        Book b = new Book();
        b.setTitle(title);
        b.setAuthors(authors.length == 0 ? null : new java.util.ArrayList<>(java.util.Arrays.asList(authors)));
        b.setPrice(price);
        b.setPages(pages);
        b.setPublished(published);
        return b;
    }
}
